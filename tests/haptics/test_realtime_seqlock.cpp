#include <gtest/gtest.h>

#include <atomic>
#include <thread>

#include "haptics/realtime/tool_snapshot.hpp"
#include "haptics/sync/seqlock.hpp"

namespace needle::haptics {
namespace {

// Every field of the snapshot carries the same counter k, so a torn read (half old, half
// new) shows up as two different values in one snapshot.
ToolSnapshot stamped(uint64_t k) {
  ToolSnapshot s;
  s.tick = k;
  const double v = static_cast<double>(k);
  for (double& x : s.needle_tip_m) x = v;
  for (double& x : s.virtual_q) x = v;
  for (double& x : s.multipliers) x = v;
  for (double& x : s.device_force_n) x = v;
  return s;
}

bool consistent(const ToolSnapshot& s) {
  const double v = static_cast<double>(s.tick);
  for (double x : s.needle_tip_m)
    if (x != v) return false;
  for (double x : s.virtual_q)
    if (x != v) return false;
  for (double x : s.multipliers)
    if (x != v) return false;
  for (double x : s.device_force_n)
    if (x != v) return false;
  return true;
}

TEST(RealtimeSeqLock, LoadReturnsTheLastStoredValue) {
  SeqLock<ToolSnapshot> lock;
  EXPECT_EQ(lock.version(), 1u);  // the constructor stores a default value
  lock.store(stamped(7));
  lock.store(stamped(9));
  const ToolSnapshot s = lock.load();
  EXPECT_EQ(s.tick, 9u);
  EXPECT_TRUE(consistent(s));
  EXPECT_EQ(lock.version(), 3u);
}

TEST(RealtimeSeqLock, ConcurrentReaderNeverSeesATornOrOlderSnapshot) {
  SeqLock<ToolSnapshot> lock;
  constexpr uint64_t kWrites = 200000;
  std::atomic<bool> done{false};
  std::thread writer([&] {
    for (uint64_t k = 1; k <= kWrites; ++k) lock.store(stamped(k));
    done = true;
  });
  uint64_t last = 0, reads = 0, torn = 0, backwards = 0;
  while (!done || last < kWrites) {
    const ToolSnapshot s = lock.load();
    if (!consistent(s)) ++torn;
    if (s.tick < last) ++backwards;
    last = s.tick;
    ++reads;
  }
  writer.join();
  EXPECT_EQ(torn, 0u);
  EXPECT_EQ(backwards, 0u);
  EXPECT_EQ(last, kWrites);
  EXPECT_GT(reads, 0u);
}

}  // namespace
}  // namespace needle::haptics
