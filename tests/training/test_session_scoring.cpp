// Per-step metrics, their combination and the score, on hand-built sessions with answers
// worked out by hand.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "tool_states.hpp"
#include "training/scoring/session_scorer.hpp"

namespace needle::training {
namespace {
using haptics::ContactState;
using test::sample;
using test::state;
constexpr double kDeg = std::numbers::pi / 180.0;

// One step that never completes (a hold of an hour), its metrics read live.
Task one_step(ConditionType type = ConditionType::kTipNear) {
  Task t;
  t.markers = {{"p", MarkerKind::kPoint, {0, 0, 0}, {}, 0}, {"down", MarkerKind::kAxis, {0, 0, 0}, {0, 0, -1}, 0}};
  Step s;
  s.id = "only";
  s.condition.type = type;
  s.condition.marker = type == ConditionType::kForceHeld ? -1 : 0;
  s.condition.within_m = 1e-9;
  s.condition.min = 1.0, s.condition.max = 3.0;
  s.condition.hold_s = 3600.0;
  t.steps = {s};
  return t;
}

TEST(StepMetrics, LateralLoadIsTheIntegralAndPeakOfTheTissueMultipliers) {
  const Task t = one_step();
  SessionScorer scorer(t);
  for (int k = 0; k <= 2000; ++k) {  // 2 s in tissue with lambda = (3, 4) N, |lambda| = 5 N
    haptics::ToolSnapshot s = state(k * 0.001, {0, 0, 0}, 0, ContactState::kTissue);
    s.multiplier_count = 2;
    s.multipliers[0] = 3.0, s.multipliers[1] = -4.0;
    scorer.feed(sample(s));
  }
  for (int k = 1; k <= 1000; ++k) {  // then 1 s on a rigid surface: its multiplier is not lateral
    haptics::ToolSnapshot s = state(2.0 + k * 0.001, {0, 0, 0}, 0, ContactState::kRigidSurface);
    s.multiplier_count = 1;
    s.multipliers[0] = 7.0;
    scorer.feed(sample(s));
  }
  const Metrics m = scorer.step_metrics(0);
  // 2 s at 5 N, plus the trapezoid of the first rigid tick falling from 5 to 0: 5 x 0.001 / 2.
  EXPECT_NEAR(m.lateral_load_Ns, 10.0 + 0.0025, 1e-9);
  EXPECT_DOUBLE_EQ(m.lateral_peak_N, 5.0);
  EXPECT_NEAR(m.duration_s, 3.0, 1e-12);
}

// What the trainee panel shows live in tissue, and what the review plots.
TEST(StepMetrics, LateralLoadNowIsTheMultipliersNormInTissueOnly) {
  haptics::ToolSnapshot s = state(0.0, {0, 0, 0}, 0, ContactState::kTissue);
  s.multiplier_count = 2;
  s.multipliers[0] = 3.0, s.multipliers[1] = -4.0;
  s.multipliers[2] = 100.0;  // beyond the count: not a multiplier of this constraint
  EXPECT_DOUBLE_EQ(lateral_load_N(s), 5.0);
  s.contact = ContactState::kRigidSurface;
  EXPECT_DOUBLE_EQ(lateral_load_N(s), 0.0);
}

// The world's force on the needle by part and as vectors: the axial force along x₅, the sideways
// hold at right angles to it, the rigid contact as it points; at the hand, times the force scale.
TEST(StepMetrics, TheNeedleForceAddsItsPartsAsVectors) {
  haptics::ToolSnapshot s = state(0.0, {0, 0, 0}, 0, ContactState::kTissue);  // x₅ = +x (identity orientation)
  s.tissue.axial_force_N = 3.0;
  s.multiplier_count = 2;
  s.multipliers[0] = 0.0, s.multipliers[1] = 4.0;
  NeedleForce f = needle_force(s);
  EXPECT_DOUBLE_EQ(f.along_N, 3.0);
  EXPECT_DOUBLE_EQ(f.sideways_N, 4.0);
  EXPECT_DOUBLE_EQ(f.rigid_N, 0.0);
  EXPECT_DOUBLE_EQ(f.total_N, 5.0);
  EXPECT_DOUBLE_EQ(hand_force_N(s, 0.25), 1.25);
  // Pressing bone from inside the tissue: the axial force and the contact add as vectors.
  s.contact = ContactState::kRigidSurface;
  s.multiplier_count = 1;
  s.tissue.axial_force_N = 5.0;
  s.environment_force_n[2] = 12.0;  // across the needle
  EXPECT_DOUBLE_EQ(needle_force(s).total_N, 13.0);
  s.environment_force_n[2] = 0.0;
  s.environment_force_n[0] = -3.0;  // against the axial force
  f = needle_force(s);
  EXPECT_DOUBLE_EQ(f.rigid_N, 3.0);
  EXPECT_DOUBLE_EQ(f.total_N, 2.0);
}

TEST(StepMetrics, ForceSteadinessIsTheSpreadOnceTheForceReachedTheBand) {
  const Task t = one_step(ConditionType::kForceHeld);  // band [1, 3] N
  SessionScorer scorer(t);
  int k = 0;
  auto feed = [&](double force, int ticks) {
    for (int i = 0; i < ticks; ++i, ++k) {
      haptics::ToolSnapshot s = state(k * 0.001, {0, 0, 0}, 0, ContactState::kRigidSurface);
      s.environment_force_n[2] = force;
      scorer.feed(sample(s));
    }
  };
  feed(0.5, 1000);  // before the band: not counted
  feed(1.5, 1000);  // a step in force from 1.5 to 2.5 N: mean 2, standard deviation 0.5
  feed(2.5, 1000);
  const Metrics m = scorer.step_metrics(0);
  EXPECT_NEAR(m.force_sd_N, 0.5, 1e-12);
  EXPECT_DOUBLE_EQ(m.peak_force_N, 2.5);
}

TEST(StepMetrics, AxisDeviationIsTheRmsAlongAGuidedAxisAndTheFinalValueWhenAligning) {
  Task t = one_step();
  t.steps[0].guidance.axis = 1;  // planned: straight down, pitch 90 degrees
  SessionScorer guided(t);
  for (int k = 0; k < 1000; ++k) guided.feed(sample(state(k * 0.001, {0, 0, 0}, (k % 2 ? 90 : 70) * kDeg)));
  EXPECT_NEAR(guided.step_metrics(0).axis_deviation_deg, std::sqrt(200.0), 1e-9);  // half at 0, half at 20

  Task align = one_step(ConditionType::kAxisAligned);
  align.steps[0].condition.marker = 1;
  align.steps[0].condition.within_rad = 1e-9;
  SessionScorer aligning(align);
  for (int k = 0; k <= 100; ++k) aligning.feed(sample(state(k * 0.01, {0, 0, 0}, (40 + 0.47 * k) * kDeg)));
  EXPECT_NEAR(aligning.step_metrics(0).axis_deviation_deg, 3.0, 1e-9);  // ends at 87 degrees
}

TEST(StepMetrics, TipErrorPathAndIdealPath) {
  Task t = one_step(ConditionType::kTargetReached);
  t.steps[0].condition.contact = ContactRequirement::kTissue;
  SessionScorer scorer(t);
  // An L: 3 cm along x, then 4 cm along y, ending (0.03, 0.04, 0) - (0, 0, 0) ... 5 cm from the
  // start; the target is at the origin, the start at (0, 0, 0.003).
  for (int k = 0; k <= 300; ++k) scorer.feed(sample(state(k * 0.01, {k * 1e-4, 0, 0.003}, 0, ContactState::kTissue)));
  for (int k = 1; k <= 400; ++k)
    scorer.feed(sample(state(3 + k * 0.01, {0.03, k * 1e-4, 0.003}, 0, ContactState::kTissue)));
  const Metrics m = scorer.step_metrics(0);
  EXPECT_NEAR(m.path_length_m, 0.07, 1e-12);
  EXPECT_NEAR(m.ideal_path_m, 0.05, 1e-12);
  EXPECT_NEAR(m.tip_error_m, std::sqrt(0.03 * 0.03 + 0.04 * 0.04 + 0.003 * 0.003), 1e-12);
  EXPECT_TRUE(std::isnan(m.force_sd_N));  // no held force in this step
}

TEST(StepMetrics, ContactEventsIgnoreChatterAndCountFaultsOnce) {
  const Task t = one_step();
  SessionScorer scorer(t);
  double now = 0.0;
  auto run = [&](ContactState c, double seconds, uint32_t fault = 0) {
    for (const double end = now + seconds; now < end - 1e-9; now += 0.001) {
      haptics::ToolSnapshot s = state(now, {0, 0, 0}, 0, c);
      s.fault = fault;
      scorer.feed(sample(s));
    }
  };
  run(ContactState::kFree, 0.5);
  run(ContactState::kTissue, 1.0);  // insertion
  run(ContactState::kFree, 0.05);   // chatter: shorter than the debounce
  run(ContactState::kTissue, 1.0);
  run(ContactState::kFree, 0.5);          // withdrawal
  run(ContactState::kTissue, 1.0);        // re-insertion
  run(ContactState::kFree, 0.5);          // withdrawal
  run(ContactState::kRigidSurface, 0.2);  // a rigid contact the step did not ask for
  run(ContactState::kFree, 0.03);
  run(ContactState::kRigidSurface, 0.2);  // the same contact (chatter)
  run(ContactState::kFree, 0.3);
  run(ContactState::kRigidSurface, 0.2, 5);  // another one, and a latched fault
  run(ContactState::kFree, 0.2, 5);
  const Metrics m = scorer.step_metrics(0);
  EXPECT_EQ(m.withdrawals, 2u);
  EXPECT_EQ(m.reinsertions, 1u);
  EXPECT_EQ(m.rigid_contacts, 2u);
  EXPECT_EQ(m.faults, 1u);
  EXPECT_EQ(m.first_fault, 5u);
}

TEST(StepMetrics, RigidContactAskedForByTheStepIsNotCounted) {
  Task t = one_step();
  t.steps[0].condition.contact = ContactRequirement::kRigidSurface;
  SessionScorer scorer(t);
  scorer.feed(sample(state(0.0, {1, 0, 0})));
  scorer.feed(sample(state(0.5, {1, 0, 0}, 0, ContactState::kRigidSurface)));
  EXPECT_EQ(scorer.step_metrics(0).rigid_contacts, 0u);
}

// Two steps whose metrics are set by hand, for the combination and the score.
std::vector<StepResult> two_results() {
  StepResult a{"a", {StepOutcome::kCompleted, 0, 10}, {}};
  a.metrics.duration_s = 10, a.metrics.tip_error_m = 0.002, a.metrics.axis_deviation_deg = 4;
  a.metrics.lateral_load_Ns = 0.25, a.metrics.lateral_peak_N = 0.5, a.metrics.peak_force_N = 1.0;
  a.metrics.path_length_m = 0.1, a.metrics.ideal_path_m = 0.08, a.metrics.normalized_jerk = 360.0;
  a.metrics.reinsertions = 1, a.metrics.tissue_time_s = 8.0, a.metrics.peak_needle_force_N = 1.0;
  StepResult b{"b", {StepOutcome::kTimedOut, 10, 30}, {}};
  b.metrics.duration_s = 20, b.metrics.axis_deviation_deg = 8, b.metrics.lateral_load_Ns = 0.25;
  b.metrics.lateral_peak_N = 0.25, b.metrics.peak_force_N = 2.0, b.metrics.force_sd_N = 0.1;
  b.metrics.path_length_m = 0.1, b.metrics.ideal_path_m = 0.02, b.metrics.rigid_contacts = 1;
  return {a, b};
}

TEST(Score, SessionMetricsSumTotalsAndAverageTheRest) {
  const Metrics m = combine_metrics(two_results());
  EXPECT_DOUBLE_EQ(m.duration_s, 30);
  EXPECT_DOUBLE_EQ(m.tip_error_m, 0.002);       // the only step with a target
  EXPECT_DOUBLE_EQ(m.axis_deviation_deg, 6.0);  // mean of 4 and 8
  EXPECT_DOUBLE_EQ(m.lateral_load_Ns, 0.5);
  EXPECT_DOUBLE_EQ(m.lateral_peak_N, 0.5);
  EXPECT_DOUBLE_EQ(m.peak_force_N, 2.0);
  EXPECT_DOUBLE_EQ(m.force_sd_N, 0.1);
  EXPECT_DOUBLE_EQ(m.path_length_m, 0.2);
  EXPECT_DOUBLE_EQ(m.ideal_path_m, 0.1);
  EXPECT_DOUBLE_EQ(m.normalized_jerk, 360.0);
  EXPECT_EQ(m.reinsertions + m.rigid_contacts, 2u);
}

TEST(Score, WeightedComponentsByHand) {
  ScoringSpec spec;  // default weights and references (docs/SCORING.md), safe force 3 N, pass 70
  const std::vector<StepResult> steps = two_results();
  const Score s = score_session(spec, steps, combine_metrics(steps));
  // completion 1/2 x 30 = 15; tip 1 - 0.002/0.01 = 0.8 x 15 = 12; axis 1 - 6/20 = 0.7 x 10 = 7;
  // lateral 1 - 0.5/1 = 0.5 x 10 = 5; peak 2 <= 3 -> 10; steadiness 1 - 0.1/0.5 = 0.8 x 5 = 4;
  // path 0.1/0.2 = 0.5 x 5 = 2.5; smoothness 1 - ln(360/sqrt360)/ln(1e6/sqrt360) x 5;
  // time: not reached (a step timed out: the task was not done) -> 0; retries 1/(1 + 2) x 5.
  const double smooth = 1.0 - std::log(std::sqrt(360.0)) / std::log(1e6 / std::sqrt(360.0));
  const double expected = 15 + 12 + 7 + 5 + 10 + 4 + 2.5 + 5 * smooth + 0 + 5.0 / 3;
  EXPECT_NEAR(s.total, expected, 1e-9);
  ASSERT_EQ(s.components.size(), 10u);
  EXPECT_EQ(s.components[7].name, "smoothness");
  EXPECT_NEAR(s.components[7].value, smooth, 1e-12);
  EXPECT_EQ(s.components[8].name, "time");
  EXPECT_EQ(s.components[8].status, ComponentStatus::kNotReached);
  EXPECT_FALSE(s.passed);
  ASSERT_EQ(s.reasons_failed.size(), 2u);  // below 70, and a step not completed
  EXPECT_NE(s.reasons_failed[1].find("1 step(s) not completed"), std::string::npos);
}

TEST(Score, PeakForceAboveTheSafeLimitCostsPointsAndFails) {
  ScoringSpec spec;
  spec.pass_score = 0.0;
  std::vector<StepResult> steps = two_results();
  steps[1].record.outcome = StepOutcome::kCompleted;
  steps[1].metrics.peak_hand_force_N = 4.5;  // 50 % over 3 N: the component drops to 0.5
  steps[1].metrics.peak_force_N = 0.0;       // the rigid contact alone is not what is scored
  const Score s = score_session(spec, steps, combine_metrics(steps));
  EXPECT_DOUBLE_EQ(s.components[4].value, 0.5);
  ASSERT_EQ(s.reasons_failed.size(), 1u);
  EXPECT_NE(s.reasons_failed[0].find("peak force at the hand 4.5 N above the safe limit 3 N"), std::string::npos);
  steps[1].metrics.peak_hand_force_N = 2.0;
  EXPECT_TRUE(score_session(spec, steps, combine_metrics(steps)).passed);
  steps[0].metrics.faults = 1;
  EXPECT_FALSE(score_session(spec, steps, combine_metrics(steps)).passed);
}

}  // namespace
}  // namespace needle::training
