// The haptic loop's health over a recording (training/sessions/loop_health.hpp), against sums made
// by hand: the rate is the ticks over the sum of their periods, the worst and p99 periods are
// order statistics, late ticks are those over kLatePeriods nominal periods, and "degraded" sits at
// its two thresholds.
#include <gtest/gtest.h>

#include "training/sessions/loop_health.hpp"

namespace needle::test {
namespace {

// A first sample (left out: its period is the wait for the start) then one per period given.
std::vector<haptics::TickSample> samples_with(const std::vector<uint64_t>& periods_ns) {
  std::vector<haptics::TickSample> s(periods_ns.size() + 1);
  s[0].period_ns = 50'000'000;
  for (size_t k = 0; k < periods_ns.size(); ++k) s[k + 1].period_ns = periods_ns[k];
  return s;
}

TEST(LoopHealth, OnTimeLoopReadsNominal) {
  const training::LoopHealth h = training::loop_health(samples_with(std::vector<uint64_t>(1000, 1'000'000)), 1000.0);
  EXPECT_EQ(h.ticks, 1000u);
  EXPECT_DOUBLE_EQ(h.rate_hz, 1000.0);
  EXPECT_DOUBLE_EQ(h.period_p99_ms, 1.0);
  EXPECT_DOUBLE_EQ(h.period_max_ms, 1.0);
  EXPECT_EQ(h.late_ticks, 0u);
  EXPECT_FALSE(h.degraded());
  EXPECT_EQ(training::describe(h),
            "haptic loop 1000.0 Hz (nominal 1000), period p99 1.00 ms, worst 1.00 ms, 0 late ticks of 1000");
}

TEST(LoopHealth, StallsCountAsLateAndLowerTheRate) {
  // 990 periods of 1 ms, 9 of 3 ms (late: over 2 ms), one of 20 ms (a stall).
  std::vector<uint64_t> p(990, 1'000'000);
  p.insert(p.end(), 9, 3'000'000);
  p.push_back(20'000'000);
  const training::LoopHealth h = training::loop_health(samples_with(p), 1000.0);
  EXPECT_EQ(h.ticks, 1000u);
  EXPECT_NEAR(h.rate_hz, 1000.0 / (0.990 + 0.027 + 0.020), 1e-9);
  EXPECT_DOUBLE_EQ(h.period_max_ms, 20.0);
  EXPECT_DOUBLE_EQ(h.period_p99_ms, 1.0);  // the 990th of 1000 in order: the last of the 1 ms ones
  EXPECT_EQ(h.late_ticks, 10u);
  EXPECT_FALSE(h.degraded());  // exactly 1 % late, the rate 3.5 % low: at neither threshold
  p[0] = 2'500'000;            // one more late tick: over 1 %, and the 990th period is now 2.5 ms
  const training::LoopHealth worse = training::loop_health(samples_with(p), 1000.0);
  EXPECT_DOUBLE_EQ(worse.period_p99_ms, 2.5);
  EXPECT_TRUE(worse.degraded());
}

TEST(LoopHealth, SlowLoopIsDegraded) {
  const training::LoopHealth h = training::loop_health(samples_with(std::vector<uint64_t>(500, 1'060'000)), 1000.0);
  EXPECT_EQ(h.late_ticks, 0u);
  EXPECT_NEAR(h.rate_hz, 1000.0 / 1.06, 1e-9);  // 5.7 % under nominal
  EXPECT_TRUE(h.degraded());
  EXPECT_NE(training::describe(h).find(": degraded"), std::string::npos);
}

TEST(LoopHealth, TooFewSamplesSayNothing) {
  const training::LoopHealth h = training::loop_health(samples_with({}), 1000.0);
  EXPECT_EQ(h.ticks, 0u);
  EXPECT_FALSE(h.degraded());
}

}  // namespace
}  // namespace needle::test
