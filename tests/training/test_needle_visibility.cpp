// The needle's visibility in an ultrasound task: the imaged slice's geometry, the step rule that
// fails a step when the tip stays out of the plane, and the needle_visibility metric and score.
#include <gtest/gtest.h>

#include <cmath>

#include "tool_states.hpp"
#include "training/scoring/session_scorer.hpp"
#include "training/tasks/task_progress.hpp"
#include "training/tasks/ultrasound_probe.hpp"

namespace needle::training {
namespace {
using haptics::ContactState;
using test::state;

// A probe on a skin at z = 0 over the origin, beams down, the array along x: its slice is
// |y| ≤ 1 mm, |x| ≤ 20 mm, z in [-50 mm, 0].
UltrasoundProbeSpec probe() {
  UltrasoundProbeSpec p;
  p.position = {0, 0, 0};
  p.slice_thickness_m = 0.002;
  return p;
}

TEST(NeedleVisibility, TheSliceIsTheImageThickenedByTheElevationBeam) {
  const UltrasoundProbeSpec p = probe();
  EXPECT_EQ(p.elevation(), (Vec3{0, -1, 0}));  // (0, 0, -1) × (1, 0, 0)
  EXPECT_TRUE(in_image_slice(p, {0.0, 0.0009, -0.01}));
  EXPECT_FALSE(in_image_slice(p, {0.0, 0.0011, -0.01}));
  EXPECT_FALSE(in_image_slice(p, {0.021, 0.0, -0.01}));  // beside the array
  EXPECT_FALSE(in_image_slice(p, {0.0, 0.0, 0.001}));    // above the face
  EXPECT_FALSE(in_image_slice(p, {0.0, 0.0, -0.051}));   // below the depth
}

TEST(NeedleVisibility, TheShareOfTheNeedleInTheSliceIsExact) {
  const UltrasoundProbeSpec p = probe();
  // In plane, down 30 mm at 45°: wholly in.
  EXPECT_DOUBLE_EQ(share_in_image_slice(p, {-0.01, 0, 0}, {0.02, 0, -0.03}), 1.0);
  // Across the plane (out-of-plane technique), 20 mm along y: the slice's 2 mm of it.
  EXPECT_NEAR(share_in_image_slice(p, {0.0, -0.01, -0.01}, {0.0, 0.01, -0.03}), 0.1, 1e-12);
  // In plane but leaving the image at 50 mm depth: the 50 mm of its 60.
  EXPECT_NEAR(share_in_image_slice(p, {0.0, 0.0, 0.0}, {0.0, 0.0, -0.06}), 50.0 / 60.0, 1e-12);
  // Parallel to the plane, 2 mm off it: none. Just in (no length): whole when the tip is in the slice.
  EXPECT_EQ(share_in_image_slice(p, {-0.01, 0.002, 0}, {0.01, 0.002, -0.02}), 0.0);
  EXPECT_EQ(share_in_image_slice(p, {0, 0, -0.01}, {0, 0, -0.01}), 1.0);
  EXPECT_EQ(share_in_image_slice(p, {0, 0.002, -0.01}, {0, 0.002, -0.01}), 0.0);
}

// One step, 20 s, "reach 25 mm deep", with the tip rule and the probe above.
Task probe_task(double out_of_plane_max_s) {
  Task t;
  t.name = "in_plane";
  t.markers = {{"target", MarkerKind::kPoint, {0.01, 0, -0.025}, {}, 0}};
  Step s;
  s.id = "advance";
  s.condition.type = ConditionType::kTargetReached;
  s.condition.marker = 0;
  s.condition.within_m = 0.001;
  s.condition.contact = ContactRequirement::kTissue;
  s.time_limit_s = 20.0;
  s.tip_out_of_plane_max_s = out_of_plane_max_s;
  t.steps = {s};
  t.ultrasound_probe = probe();
  t.scoring.weights.needle_visibility = ScoreWeights::kDefaultNeedleVisibility;
  return t;
}

TEST(NeedleVisibility, ATipOutOfThePlaneTooLongEndsTheStep) {
  const Task t = probe_task(1.0);
  TaskProgress p(t);
  p.feed(state(0.0, {0, 0, 0.01}));                                  // above the skin: no rule
  p.feed(state(1.0, {0, 0.005, -0.005}, 0, ContactState::kTissue));  // out of plane, in tissue: the clock starts
  p.feed(state(1.9, {0, 0.005, -0.01}, 0, ContactState::kTissue));
  p.feed(state(2.0, {0, 0.0, -0.01}, 0, ContactState::kTissue));  // back in plane at 1 s: the clock stops
  p.feed(state(2.5, {0, 0.005, -0.012}, 0, ContactState::kTissue));
  p.feed(state(3.4, {0, 0.005, -0.012}, 0, ContactState::kTissue));
  EXPECT_EQ(p.records()[0].outcome, StepOutcome::kActive);
  p.feed(state(3.5, {0, 0.005, -0.012}, 0, ContactState::kTissue));  // 1 s out of plane
  EXPECT_EQ(p.records()[0].outcome, StepOutcome::kTipLost);
  EXPECT_EQ(p.records()[0].end_s, 3.5);
  EXPECT_STREQ(step_outcome_name(StepOutcome::kTipLost), "tip_lost");
  StepOutcome o;
  EXPECT_TRUE(step_outcome_from_name("tip_lost", o));
  EXPECT_EQ(o, StepOutcome::kTipLost);
}

SessionResult scored(const Task& t, double y_offset) {
  SessionScorer scorer(t);
  scorer.feed(test::sample(state(0.0, {-0.01, y_offset, 0.005})));
  // Enters at (−10 mm, y, 0) and goes 45° down in x, 1 mm a tick of 0.1 s, to the target's depth.
  for (int k = 0; k <= 25; ++k)
    scorer.feed(
        test::sample(state(0.1 + 0.1 * k, {-0.01 + 0.001 * k, y_offset, -0.001 * k}, 0.0, ContactState::kTissue)));
  return scorer.result();
}

TEST(NeedleVisibility, TheMetricIsTheTimeMeanShareAndTheScoreWeighsIt) {
  const Task t = probe_task(0.0);
  const SessionResult in_plane = scored(t, 0.0);
  EXPECT_DOUBLE_EQ(in_plane.steps[0].metrics.needle_visibility, 1.0);
  EXPECT_DOUBLE_EQ(in_plane.overall.needle_visibility, 1.0);
  // 2 mm off the plane, parallel to it: never in the 1 mm half-slice.
  const SessionResult beside = scored(t, 0.002);
  EXPECT_EQ(beside.steps[0].metrics.needle_visibility, 0.0);
  const auto component = [](const SessionResult& r) {
    for (const ScoreComponent& c : r.score.components)
      if (c.name == "needle_visibility") return c;
    return ScoreComponent{"missing", -1.0, 0.0};
  };
  EXPECT_EQ(component(in_plane).value, 1.0);
  EXPECT_EQ(component(beside).value, 0.0);
  // The hand-built task's weights (the defaults, 100, and the probe's 10) renormalised to 100.
  EXPECT_NEAR(component(in_plane).weight, ScoreWeights::kDefaultNeedleVisibility * 100.0 / 110.0, 1e-12);
  // Without a probe there is no metric and no component.
  Task plain = t;
  plain.ultrasound_probe.reset();
  plain.scoring.weights.needle_visibility = 0.0;
  const SessionResult none = scored(plain, 0.0);
  EXPECT_TRUE(std::isnan(none.overall.needle_visibility));
  EXPECT_EQ(component(none).name, "missing");
}

}  // namespace
}  // namespace needle::training
