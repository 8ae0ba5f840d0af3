// Newest-only hand-off of a trivially copyable value from one writer to any number of
// readers, without locks: the writer never waits, a reader retries while a write is under
// way. The payload is stored as relaxed atomic words so no access is a data race.
#pragma once

#include <atomic>
#include <cstdint>
#include <cstring>
#include <type_traits>

namespace needle::haptics {

template <typename T>
class SeqLock {
  static_assert(std::is_trivially_copyable_v<T>);
  static constexpr std::size_t kWords = (sizeof(T) + sizeof(uint64_t) - 1) / sizeof(uint64_t);

 public:
  SeqLock() { store(T{}); }

  // Single writer only.
  void store(const T& value) noexcept {
    uint64_t words[kWords] = {};
    std::memcpy(words, &value, sizeof(T));
    const uint64_t seq = sequence_.load(std::memory_order_relaxed);
    sequence_.store(seq + 1, std::memory_order_relaxed);  // odd: write under way
    std::atomic_thread_fence(std::memory_order_release);
    for (std::size_t i = 0; i < kWords; ++i) words_[i].store(words[i], std::memory_order_relaxed);
    sequence_.store(seq + 2, std::memory_order_release);
  }

  // Any thread. Returns a value that was stored as a whole, never a mix of two.
  T load() const noexcept {
    uint64_t words[kWords];
    for (;;) {
      const uint64_t before = sequence_.load(std::memory_order_acquire);
      if (before & 1u) continue;
      for (std::size_t i = 0; i < kWords; ++i) words[i] = words_[i].load(std::memory_order_relaxed);
      std::atomic_thread_fence(std::memory_order_acquire);
      if (sequence_.load(std::memory_order_relaxed) == before) break;
    }
    T value;
    std::memcpy(&value, words, sizeof(T));
    return value;
  }

  // How many values have been stored (readers can tell whether something is new).
  uint64_t version() const noexcept { return sequence_.load(std::memory_order_acquire) / 2; }

 private:
  std::atomic<uint64_t> sequence_{0};
  std::atomic<uint64_t> words_[kWords];
};

}  // namespace needle::haptics
