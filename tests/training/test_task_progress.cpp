// Conditions and the step state machine on hand-built haptic states.
#include <gtest/gtest.h>

#include <algorithm>
#include <numbers>

#include "tool_states.hpp"
#include "training/tasks/condition.hpp"
#include "training/tasks/task_progress.hpp"

namespace needle::training {
namespace {
using haptics::ContactState;
using test::state;
constexpr double kDeg = std::numbers::pi / 180.0;

// Markers: a point at the origin, an axis pointing down -z from (0, 0, 0.1), a sphere r = 0.1 at
// (0, 0, -0.1) (so its top is the origin).
Task three_markers() {
  Task t;
  t.name = "test";
  t.markers = {{"p", MarkerKind::kPoint, {0, 0, 0}, {}, 0},
               {"down", MarkerKind::kAxis, {0, 0, 0.1}, {0, 0, -1}, 0},
               {"ball", MarkerKind::kSurfaceNormal, {0, 0, -0.1}, {}, 0.1}};
  return t;
}

Condition condition(ConditionType type, int marker) {
  Condition c;
  c.type = type;
  c.marker = marker;
  return c;
}

TEST(Conditions, TipNearIsADistanceAndNeedsTheContact) {
  const Task t = three_markers();
  Condition c = condition(ConditionType::kTipNear, 0);
  c.within_m = 0.01;
  EXPECT_TRUE(condition_holds(t, c, state(0, {0.006, 0.008, 0})));  // 10 mm exactly
  EXPECT_FALSE(condition_holds(t, c, state(0, {0.006, 0.0081, 0})));
  c.contact = ContactRequirement::kRigidSurface;
  EXPECT_FALSE(condition_holds(t, c, state(0, {0, 0, 0})));
  EXPECT_TRUE(condition_holds(t, c, state(0, {0, 0, 0}, 0, ContactState::kRigidSurface)));
}

TEST(Conditions, AxisAlignedComparesTheNeedleAxisWithThePlannedOne) {
  const Task t = three_markers();
  Condition c = condition(ConditionType::kAxisAligned, 1);  // planned: straight down
  c.within_rad = 10 * kDeg;
  // Pitch 90 degrees turns +x to -z; 81 and 99 degrees are 9 degrees off, 79 is 11 off.
  EXPECT_TRUE(condition_holds(t, c, state(0, {0, 0, 0}, 90 * kDeg)));
  EXPECT_TRUE(condition_holds(t, c, state(0, {0, 0, 0}, 81 * kDeg)));
  EXPECT_TRUE(condition_holds(t, c, state(0, {0, 0, 0}, 99 * kDeg)));
  EXPECT_FALSE(condition_holds(t, c, state(0, {0, 0, 0}, 79 * kDeg)));
  // The sphere's inward normal under a tip at 45 degrees on its surface points at the centre.
  Condition n = condition(ConditionType::kAxisAligned, 2);
  n.within_rad = 1 * kDeg;
  const double r = 0.1 / std::sqrt(2.0);
  const Vec3 tip{-r, 0, -0.1 + r};  // axis towards the centre: (1, 0, -1)/sqrt2, pitch 45 degrees
  EXPECT_TRUE(condition_holds(t, n, state(0, tip, 45 * kDeg)));
  EXPECT_FALSE(condition_holds(t, n, state(0, tip, 47 * kDeg)));
}

TEST(Conditions, DepthForceTargetAndWithdrawal) {
  const Task t = three_markers();
  Condition depth = condition(ConditionType::kDepthInBand, 1);
  depth.min = 0.02, depth.max = 0.03;
  EXPECT_NEAR(depth_along(t.markers[1], {0.5, 0.2, 0.075}), 0.025, 1e-15);  // lateral offset ignored
  EXPECT_TRUE(condition_holds(t, depth, state(0, {0.5, 0.2, 0.075})));
  EXPECT_FALSE(condition_holds(t, depth, state(0, {0, 0, 0.065})));

  Condition force = condition(ConditionType::kForceHeld, -1);
  force.min = 1.0, force.max = 2.0;
  haptics::ToolSnapshot s = state(0, {0, 0, 0});
  s.environment_force_n[0] = 0.9, s.environment_force_n[1] = 1.2;  // |F| = 1.5
  EXPECT_TRUE(condition_holds(t, force, s));
  s.environment_force_n[2] = 1.5;  // |F| = sqrt(0.81 + 1.44 + 2.25) = 2.12
  EXPECT_FALSE(condition_holds(t, force, s));

  Condition target = condition(ConditionType::kTargetReached, 0);
  target.within_m = 0.005;
  target.contact = ContactRequirement::kTissue;
  EXPECT_TRUE(condition_holds(t, target, state(0, {0, 0.004, 0}, 0, ContactState::kTissue)));
  EXPECT_FALSE(condition_holds(t, target, state(0, {0, 0.004, 0}, 0, ContactState::kFree)));

  Condition out = condition(ConditionType::kWithdrawn, 0);
  out.within_m = 0.01;
  out.contact = ContactRequirement::kFree;
  EXPECT_TRUE(condition_holds(t, out, state(0, {0, 0, 0.011})));
  EXPECT_FALSE(condition_holds(t, out, state(0, {0, 0, 0.009})));
  EXPECT_FALSE(condition_holds(t, out, state(0, {0, 0, 0.02}, 0, ContactState::kTissue)));
}

// Two steps: reach the point (held 0.5 s, 3 s limit), then go 2 cm deep along "down".
Task two_steps() {
  Task t = three_markers();
  Step reach;
  reach.id = "reach";
  reach.condition = condition(ConditionType::kTipNear, 0);
  reach.condition.within_m = 0.01;
  reach.condition.hold_s = 0.5;
  reach.time_limit_s = 3.0;
  Step deep;
  deep.id = "deep";
  deep.condition = condition(ConditionType::kDepthInBand, 1);
  deep.condition.min = 0.12, deep.condition.max = 0.13;
  t.steps = {reach, deep};
  return t;
}

TEST(TaskProgress, AStepCompletesWhenItsConditionHoldsWithoutABreakForItsHoldTime) {
  const Task t = two_steps();
  TaskProgress p(t);
  EXPECT_EQ(p.records()[0].outcome, StepOutcome::kPending);
  p.feed(state(1.0, {0.05, 0, 0}));  // starts step 0, far away
  EXPECT_EQ(p.records()[0].outcome, StepOutcome::kActive);
  EXPECT_DOUBLE_EQ(p.records()[0].start_s, 1.0);
  p.feed(state(1.25, {0, 0, 0}));  // near from 1.25 s
  p.feed(state(1.5, {0, 0, 0}));
  EXPECT_TRUE(p.condition_met());
  EXPECT_DOUBLE_EQ(p.held_s(), 0.25);
  p.feed(state(1.625, {0.02, 0, 0}));  // a break: the hold starts again
  EXPECT_FALSE(p.condition_met());
  p.feed(state(1.75, {0, 0, 0}));
  p.feed(state(2.0, {0, 0, 0}));
  EXPECT_EQ(p.current_step(), 0u);
  p.feed(state(2.25, {0, 0, 0}));  // held 0.5 s since 1.75
  EXPECT_EQ(p.current_step(), 1u);
  EXPECT_EQ(p.records()[0].outcome, StepOutcome::kCompleted);
  EXPECT_DOUBLE_EQ(p.records()[0].end_s, 2.25);
  EXPECT_DOUBLE_EQ(p.records()[1].start_s, 2.25);  // the next starts on the same state
  EXPECT_EQ(p.records()[1].outcome, StepOutcome::kActive);
  p.feed(state(3.0, {0, 0, -0.025}));  // depth 0.125: no hold time, done at once
  EXPECT_TRUE(p.finished());
  EXPECT_EQ(p.records()[1].outcome, StepOutcome::kCompleted);
  EXPECT_DOUBLE_EQ(p.records()[1].end_s, 3.0);
  p.feed(state(4.0, {0, 0, 0}));  // ignored once finished
  EXPECT_DOUBLE_EQ(p.records()[1].end_s, 3.0);
}

TEST(TaskProgress, TheTimeLimitEndsAStepAndTheNextOneStarts) {
  const Task t = two_steps();
  TaskProgress p(t);
  p.feed(state(10.0, {1, 0, 0}));
  p.feed(state(12.9, {1, 0, 0}));
  EXPECT_EQ(p.current_step(), 0u);
  p.feed(state(13.0, {1, 0, 0}));  // 3 s since the start
  EXPECT_EQ(p.records()[0].outcome, StepOutcome::kTimedOut);
  EXPECT_DOUBLE_EQ(p.records()[0].end_s, 13.0);
  EXPECT_EQ(p.current_step(), 1u);
  EXPECT_DOUBLE_EQ(p.records()[1].start_s, 13.0);
}

TEST(TaskProgress, MovingTheTipInAFixedTipStepFailsIt) {
  Task t = two_steps();
  t.steps[0].tip_fixed_within_m = 0.003;
  t.steps[0].time_limit_s = 0.0;
  t.steps[0].condition.marker = 0;
  t.steps[0].condition.within_m = 0.001;
  t.steps[0].condition.hold_s = 10.0;
  TaskProgress p(t);
  p.feed(state(0.0, {0.1, 0, 0}));
  p.feed(state(1.0, {0.1, 0.002, 0.002}));  // 2.8 mm from the start: still fine
  EXPECT_EQ(p.current_step(), 0u);
  p.feed(state(2.0, {0.1, 0.003, 0.0}));  // 3 mm exactly: fine
  EXPECT_EQ(p.current_step(), 0u);
  p.feed(state(3.0, {0.1, 0.0031, 0.0}));
  EXPECT_EQ(p.records()[0].outcome, StepOutcome::kTipMoved);
  EXPECT_EQ(p.current_step(), 1u);
}

// Layers as the scenario lists them: skin 0, fat 1, dura 2, bone 3.
Task layered_steps() {
  Task t;
  t.name = "layers";
  t.layers = {{"skin", false}, {"fat", false}, {"dura", false}, {"bone", true}};
  Step in_fat;
  in_fat.id = "in_fat";
  in_fat.condition.type = ConditionType::kTipInLayer;
  in_fat.condition.layer = 1;
  in_fat.condition.hold_s = 1.0;
  in_fat.forbidden_punctures = 1u << 2;
  in_fat.forbidden_touches = 1u << 3;
  Step skin_done = in_fat;
  skin_done.id = "skin_done";
  skin_done.condition.type = ConditionType::kPunctured;
  skin_done.condition.layer = 0;
  skin_done.condition.hold_s = 0.0;
  t.steps = {in_fat, skin_done};
  return t;
}

haptics::ToolSnapshot in_layer(double t, int layer, uint32_t punctured, int bone = -1) {
  haptics::ToolSnapshot s = state(t, {0, 0, 0}, 0.0, ContactState::kTissue);
  s.tissue.tip_layer = layer;
  s.tissue.punctured_layers = punctured;
  s.tissue.bone_layer = bone;
  return s;
}

TEST(Conditions, TipInLayerAndPuncturedReadTheTissueSnapshot) {
  const Task t = layered_steps();
  const Condition& in_fat = t.steps[0].condition;
  const Condition& skin = t.steps[1].condition;
  EXPECT_FALSE(condition_holds(t, in_fat, in_layer(0, -1, 0)));
  EXPECT_FALSE(condition_holds(t, in_fat, in_layer(0, 0, 0b1)));
  EXPECT_TRUE(condition_holds(t, in_fat, in_layer(0, 1, 0b11)));
  EXPECT_FALSE(condition_holds(t, in_fat, in_layer(0, 2, 0b111)));
  EXPECT_FALSE(condition_holds(t, skin, in_layer(0, -1, 0)));
  EXPECT_TRUE(condition_holds(t, skin, in_layer(0, 0, 0b1)));
  EXPECT_TRUE(condition_holds(t, skin, in_layer(0, -1, 0b1)));  // pulled back out of it, on the same track
}

TEST(TaskProgress, AForbiddenPunctureEndsTheStepWithTheLayerNamed) {
  const Task t = layered_steps();
  TaskProgress p(t);
  p.feed(in_layer(0.0, 0, 0b1));
  p.feed(in_layer(0.5, 1, 0b11));
  p.feed(in_layer(1.0, 2, 0b111));  // through the dura before the hold in the fat was over
  EXPECT_EQ(p.records()[0].outcome, StepOutcome::kForbiddenPuncture);
  EXPECT_EQ(p.records()[0].layer, 2);
  EXPECT_DOUBLE_EQ(p.records()[0].end_s, 1.0);
  EXPECT_EQ(step_failure_reason(t, p.records()[0]), "dura punctured (forbidden)");
  // The next step forbids the dura too, but it was punctured already: that is not a new fault;
  // the skin is punctured, so the step completes.
  p.feed(in_layer(1.5, 2, 0b111));
  EXPECT_EQ(p.records()[1].outcome, StepOutcome::kCompleted);
}

TEST(TaskProgress, TouchingAForbiddenRigidLayerEndsTheStep) {
  const Task t = layered_steps();
  TaskProgress p(t);
  p.feed(in_layer(0.0, 1, 0b11));
  p.feed(in_layer(0.5, 1, 0b11, 3));  // on bone, in the fat
  EXPECT_EQ(p.records()[0].outcome, StepOutcome::kRigidTouched);
  EXPECT_EQ(p.records()[0].layer, 3);
  EXPECT_EQ(step_failure_reason(t, p.records()[0]), "bone touched (forbidden)");
  p.feed(in_layer(0.55, 1, 0b11));    // off the bone for 50 ms and on it again: the penalty's chatter,
  p.feed(in_layer(0.6, 1, 0b11, 3));  // the same touch, no new fault; the skin is punctured
  EXPECT_EQ(p.records()[1].outcome, StepOutcome::kCompleted);
  // A completed step has no failure reason; a forbidden fault wins over success on the same state.
  EXPECT_EQ(step_failure_reason(t, p.records()[1]), "");
  TaskProgress q(t);
  q.feed(in_layer(0.0, 1, 0b11));
  q.feed(in_layer(1.0, 1, 0b111));  // the hold is over and the dura punctured on the same state
  EXPECT_EQ(q.records()[0].outcome, StepOutcome::kForbiddenPuncture);
}

TEST(TaskProgress, OutcomesHaveNames) {
  EXPECT_STREQ(step_outcome_name(StepOutcome::kForbiddenPuncture), "forbidden_puncture");
  EXPECT_STREQ(step_outcome_name(StepOutcome::kRigidTouched), "rigid_touched");
  StepOutcome o{};
  EXPECT_TRUE(step_outcome_from_name("rigid_touched", o));
  EXPECT_EQ(o, StepOutcome::kRigidTouched);
  EXPECT_STREQ(step_outcome_name(StepOutcome::kTimedOut), "timed_out");
  EXPECT_STREQ(step_outcome_name(StepOutcome::kTipMoved), "tip_moved");
  EXPECT_STREQ(step_outcome_name(StepOutcome::kCompleted), "completed");
}

}  // namespace
}  // namespace needle::training
