// The allocation counter's state: start() arms it, stop() returns the calls into the C allocator
// counted since. Any translation unit of a test program may include this; the counting itself is
// tests/support/allocation_counter.hpp, in exactly one translation unit of that program. Nothing
// the product ships counts its allocations: needle-sim keeps the C library's allocator.
#pragma once

#include <atomic>

namespace needle::test::allocation_counter {

inline std::atomic<long> calls{0};
inline std::atomic<bool> armed{false};

inline void start() {
  calls = 0;
  armed = true;
}
inline long stop() {
  armed = false;
  return calls.load();
}
inline void note() {
  if (armed.load(std::memory_order_relaxed)) calls.fetch_add(1, std::memory_order_relaxed);
}

}  // namespace needle::test::allocation_counter
