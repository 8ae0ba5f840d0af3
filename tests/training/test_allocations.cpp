// The scorer runs beside the haptic thread: once built, feeding it allocates nothing. Checked on
// the shipped penetrable-sphere task with a scripted ideal operator that completes every step.
// (This is the one translation unit of training_tests that defines the counting allocator.)
#include <gtest/gtest.h>

#include <algorithm>
#include <numbers>

#include "tests/support/allocation_counter.hpp"
#include "tests/support/test_paths.hpp"
#include "tool_states.hpp"
#include "training/scoring/session_scorer.hpp"

namespace needle::training {
namespace {
using haptics::ContactState;
constexpr double kPi = std::numbers::pi;

// Linear blend from a to b as t goes from t0 to t1, held outside.
double ramp(double t, double t0, double t1, double a, double b) {
  return a + (b - a) * std::clamp((t - t0) / (t1 - t0), 0.0, 1.0);
}

// The thesis's section 4.4 motion, with a withdrawal added: approach along the 45 degree line,
// insert 3 cm, pivot to vertical about the tip, advance 2 cm, pull out vertically.
haptics::ToolSnapshot ideal_penetrable(double t) {
  const Vec3 dir{std::sqrt(0.5), 0.0, -std::sqrt(0.5)};
  const Vec3 entry{0.4 - 0.1 * std::sqrt(0.5), 0.0, 0.1 * std::sqrt(0.5)};
  const Vec3 pivot = entry + 0.03 * dir;
  Vec3 tip;
  double pitch = kPi / 4;
  if (t < 7.0) {
    tip = entry + ramp(t, 0.0, 2.0, -0.05, 0.0) * dir + ramp(t, 2.0, 6.0, 0.0, 0.03) * dir;
  } else {
    pitch = ramp(t, 7.0, 12.0, kPi / 4, kPi / 2);
    tip = pivot + Vec3{0.0, 0.0, -ramp(t, 13.0, 17.0, 0.0, 0.02) + ramp(t, 18.0, 22.0, 0.0, 0.08)};
  }
  const bool inside = distance(tip, {0.4, 0.0, 0.0}) < 0.1;
  return test::state(t, tip, pitch, inside ? ContactState::kTissue : ContactState::kFree);
}

TEST(Allocations, FeedingTheScorerAllocatesNothing) {
  const Task task = load_task(needle::test::source_dir().string() + "/assets/tasks/penetrable_sphere.json");
  SessionScorer scorer(task);
  needle::test::allocation_counter::start();
  for (int k = 0; k <= 23000; ++k) {
    haptics::ToolSnapshot s = ideal_penetrable(k * 0.001);
    s.multiplier_count = 2;
    s.multipliers[0] = 0.1;
    scorer.feed(test::sample(s));
  }
  const long allocations = needle::test::allocation_counter::stop();
  EXPECT_EQ(allocations, 0);
  const SessionResult r = scorer.result();
  ASSERT_TRUE(r.finished);
  for (const StepResult& step : r.steps) EXPECT_EQ(step.record.outcome, StepOutcome::kCompleted) << step.id;
  EXPECT_EQ(r.overall.withdrawals, 1u);
  EXPECT_EQ(r.overall.reinsertions, 0u);
  EXPECT_TRUE(r.score.passed) << r.score.total;
}

}  // namespace
}  // namespace needle::training
