#include <gtest/gtest.h>

#include <thread>

#include "haptics/sync/spsc_ring.hpp"

namespace needle::haptics {
namespace {

TEST(RealtimeRing, CapacityRoundsUpToAPowerOfTwo) {
  EXPECT_EQ(SpscRing<int>(5).capacity(), 8u);
  EXPECT_EQ(SpscRing<int>(8).capacity(), 8u);
}

TEST(RealtimeRing, OverflowDropsTheNewestAndCountsEachDrop) {
  SpscRing<int> ring(4);
  for (int i = 0; i < 10; ++i) ring.push(i);
  EXPECT_EQ(ring.overflowed(), 6u);
  EXPECT_EQ(ring.pushed(), 4u);
  int v = -1;
  for (int i = 0; i < 4; ++i) {
    ASSERT_TRUE(ring.pop(v));
    EXPECT_EQ(v, i);  // the oldest survive, in order
  }
  EXPECT_FALSE(ring.pop(v));
  EXPECT_TRUE(ring.push(42));  // room again after draining
  ASSERT_TRUE(ring.pop(v));
  EXPECT_EQ(v, 42);
}

TEST(RealtimeRing, EveryElementIsEitherDeliveredInOrderOrCountedAsOverflow) {
  SpscRing<uint64_t> ring(64);
  constexpr uint64_t kCount = 500000;
  std::thread producer([&] {
    for (uint64_t i = 0; i < kCount; ++i) ring.push(i);
  });
  uint64_t received = 0, last = 0, out_of_order = 0, v = 0;
  bool first = true;
  while (true) {
    if (ring.pop(v)) {
      if (!first && v <= last) ++out_of_order;
      last = v;
      first = false;
      ++received;
    } else if (ring.pushed() + ring.overflowed() == kCount && received == ring.pushed()) {
      break;
    }
  }
  producer.join();
  EXPECT_EQ(out_of_order, 0u);
  EXPECT_EQ(received + ring.overflowed(), kCount);
}

}  // namespace
}  // namespace needle::haptics
