#include <gtest/gtest.h>

#include "haptics/realtime/loop_stats.hpp"
#include "haptics/realtime/periodic_timer.hpp"

namespace needle::haptics {
namespace {

TEST(RealtimeStats, PeriodErrorComputeOverrunsAndRate) {
  LoopStats stats;
  stats.set_nominal_rate(1000.0);
  // Periods alternate 0.9 ms and 1.1 ms: every period is 100 us off, the mean is 1 ms.
  for (int k = 0; k < 2000; ++k) stats.record(k % 2 ? 1100000 : 900000, 1000000, 20000 + k, k == 7);
  const LoopStatsSummary s = stats.summary();
  EXPECT_EQ(s.ticks, 2000u);
  EXPECT_EQ(s.overruns, 1u);
  EXPECT_NEAR(s.period_error.p50_ns, 100000.0, 100000.0 / 32);
  EXPECT_EQ(s.period_error.max_ns, 100000.0);
  EXPECT_EQ(s.compute.max_ns, 21999.0);
  EXPECT_NEAR(s.compute.p50_ns, 21000.0, 21000.0 / 32);
  EXPECT_NEAR(s.rate_hz, 1000.0, 1000.0 * 0.1 / 256 * 2) << "exponential mean of alternating periods";
  EXPECT_EQ(s.nominal_rate_hz, 1000.0);
  stats.clear();
  EXPECT_EQ(stats.summary().period_error.count, 0u);
  EXPECT_EQ(stats.summary().overruns, 0u);
}

// Deadlines one second apart: no sleeping needed and no timing assumption in practice.
TEST(RealtimeTimer, AdvanceMovesOnePeriodAndRestartsAfterAnOverrun) {
  const int64_t second = 1'000'000'000;
  PeriodicTimer timer(second);
  timer.start();
  const int64_t now = monotonic_ns();
  EXPECT_FALSE(timer.advance(now)) << "work ended well before the next deadline";
  EXPECT_TRUE(timer.advance(now + 10 * second)) << "work ended after the next deadline";
  // The schedule restarted at the overrunning tick's end: the next deadline is one period on.
  EXPECT_FALSE(timer.advance(now + 11 * second));
  EXPECT_TRUE(timer.advance(now + 12 * second + 1));
}

}  // namespace
}  // namespace needle::haptics
