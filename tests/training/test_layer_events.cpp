// The layered tissue's events and metrics on hand-built states: a needle going straight
// down the z axis through skin (0), fat (1), the flavum (2), the epidural space (3) and the dura (4),
// with a bone (5); membranes are the layers with a puncture force.
#include <gtest/gtest.h>

#include <algorithm>
#include <numbers>

#include "tool_states.hpp"
#include "training/scoring/layer_events.hpp"
#include "training/scoring/session_scorer.hpp"

namespace needle::training {
namespace {
using haptics::ContactState;

Task spine() {
  Task t;
  t.name = "spine";
  t.layers = {{"skin", false, 1.2},     {"fat", false, 0.0},  {"flavum", false, 5.0},
              {"epidural", false, 0.0}, {"dura", false, 1.0}, {"bone", true, 0.0}};
  Step s;
  s.id = "in";
  s.condition.type = ConditionType::kTipInLayer;
  s.condition.layer = 3;
  s.condition.hold_s = 100.0;  // never completes: every state falls in this step
  s.forbidden_punctures = 1u << 4;
  t.steps = {s};
  return t;
}

// The needle pointing down (-z): pitch 90 degrees turns +x onto -z.
haptics::ToolSnapshot down(double t, double z, int layer, uint32_t passed, double force = 0.0, int bone = -1) {
  haptics::ToolSnapshot s =
      test::state(t, {0, 0, z}, std::numbers::pi / 2, layer >= 0 ? ContactState::kTissue : ContactState::kFree);
  s.tissue.tip_layer = layer;
  s.tissue.punctured_layers = passed;
  s.tissue.axial_force_N = force;
  s.tissue.bone_layer = bone;
  if (bone >= 0) s.tissue.bone_force_n[2] = -2.0 * force;
  return s;
}

TEST(LayerEvents, PuncturesInOrderWithDepthAndThePopsPeak) {
  const Task t = spine();
  LayerEventTracker tracker(t);
  const Vec3 entry{0, 0, 0};
  haptics::ToolSnapshot tenting = down(0.0, 0.0, -1, 0, 0.5);
  tenting.tissue.surface_layer = 0;
  tracker.feed(tenting, nullptr);
  tenting = down(0.1, -0.002, -1, 0, 1.3);  // tenting the skin: the peak
  tenting.tissue.surface_layer = 0;
  tracker.feed(tenting, nullptr);
  LayerEvents e = tracker.feed(down(0.2, -0.003, 0, 0b1, 0.4), &entry);  // through
  EXPECT_EQ(e.punctured, 0b1u);
  e = tracker.feed(down(0.3, -0.006, 1, 0b11, 0.6), &entry);  // into the fat: no membrane
  EXPECT_EQ(e.passed, 0b10u);
  EXPECT_EQ(e.punctured, 0u);
  tracker.feed(down(0.4, -0.020, 1, 0b11, 4.8), &entry);
  tracker.feed(down(0.5, -0.022, 2, 0b111, 2.0), &entry);  // the flavum gives way
  ASSERT_EQ(tracker.punctures().size(), 2u);
  EXPECT_EQ(tracker.punctures()[0].layer, 0);
  EXPECT_DOUBLE_EQ(tracker.punctures()[0].peak_force_N, 1.3);
  EXPECT_DOUBLE_EQ(tracker.punctures()[0].depth_m, 0.003);
  EXPECT_DOUBLE_EQ(tracker.punctures()[0].t_s, 0.2);
  EXPECT_EQ(tracker.punctures()[1].layer, 2);
  EXPECT_DOUBLE_EQ(tracker.punctures()[1].peak_force_N, 4.8);  // the largest since the skin's puncture
  EXPECT_DOUBLE_EQ(tracker.punctures()[1].depth_m, 0.022);
}

TEST(LayerEvents, TheRunAfterAPunctureIsTheTravelAlongTheNeedleUntilItStops) {
  const Task t = spine();
  LayerEventTracker tracker(t);
  tracker.feed(down(0.0, -0.040, 1, 0b11), nullptr);
  tracker.feed(down(0.01, -0.041, 1, 0b11), nullptr);
  // The flavum gives way at z = -41 mm: the tip runs 6 mm in 60 ms, through the dura on the way
  // (the same run), then creeps at 1 mm/s (stopped after 0.1 s of that).
  LayerEvents e = tracker.feed(down(0.02, -0.043, 3, 0b1111), nullptr);
  EXPECT_EQ(e.punctured, 0b100u);
  EXPECT_NEAR(e.run_m, 0.002, 1e-12);
  tracker.feed(down(0.05, -0.045, 3, 0b1111), nullptr);
  e = tracker.feed(down(0.08, -0.047, 4, 0b11111), nullptr);
  EXPECT_EQ(e.punctured, 0b10000u);
  EXPECT_NEAR(e.run_m, 0.006, 1e-12);
  double z = -0.047;
  for (int k = 1; k <= 30; ++k) e = tracker.feed(down(0.08 + 0.01 * k, z -= 1e-5, 4, 0b11111), nullptr);
  const double stopped = e.run_m;
  EXPECT_NEAR(stopped, 0.006 + 1e-5 * 11, 1.5e-5);  // stopped 0.1 s after the creep began: 11 (or 12) more steps
  e = tracker.feed(down(0.5, -0.060, 4, 0b11111), nullptr);  // a later advance is not the run's
  EXPECT_DOUBLE_EQ(e.run_m, stopped);
}

TEST(LayerEvents, BoneContactsAreDebouncedAndRedirectionsNeedAReAdvance) {
  const Task t = spine();
  LayerEventTracker tracker(t);
  int contacts = 0, redirections = 0;
  auto feed = [&](const haptics::ToolSnapshot& s) {
    const LayerEvents& e = tracker.feed(s, nullptr);
    contacts += e.bone_entry;
    redirections += e.redirection;
  };
  feed(down(0.0, -0.01, 1, 0b11));
  feed(down(0.1, -0.02, 1, 0b11, 1.0, 5));   // on bone
  feed(down(0.2, -0.02, 1, 0b11, 1.0, -1));  // chatter: off 0.1 s
  feed(down(0.3, -0.02, 1, 0b11, 1.0, 5));   // the same contact
  EXPECT_EQ(contacts, 1);
  feed(down(0.4, -0.018, 1, 0b11));
  feed(down(1.0, -0.018, 1, 0b11, 1.0, 5));  // 0.6 s later: a second contact
  EXPECT_EQ(contacts, 2);
  feed(down(1.1, -0.02, 2, 0b111));  // deeper: the flavum
  feed(down(1.2, -0.01, 1, 0b111));  // pulled back into the fat
  EXPECT_EQ(redirections, 0);
  feed(down(1.3, -0.005, 0, 0b111));  // further back, still on the track
  feed(down(1.4, -0.012, 1, 0b111));  // and in again
  EXPECT_EQ(redirections, 1);
  feed(down(1.5, 0.01, -1, 0));  // out: a new track
  feed(down(1.6, -0.005, 0, 0b1));
  EXPECT_EQ(redirections, 1);
}

TEST(LayerEvents, TheScorerCountsThemPerStepAndListsThePunctures) {
  const Task t = spine();
  SessionScorer scorer(t);
  scorer.feed(test::sample(down(0.0, 0.001, -1, 0, 0.0)));
  scorer.feed(test::sample(down(0.1, -0.003, 0, 0b1, 1.4)));
  scorer.feed(test::sample(down(0.2, -0.040, 2, 0b111, 5.0)));
  scorer.feed(test::sample(down(0.3, -0.050, 4, 0b11111, 1.0, 5)));  // through the dura onto bone
  const SessionResult r = scorer.result();
  const Metrics& m = r.steps[0].metrics;
  EXPECT_EQ(m.punctures, 3u);  // skin, flavum, dura
  EXPECT_EQ(m.forbidden_punctures, 1u);
  EXPECT_EQ(m.bone_contacts, 1u);
  EXPECT_DOUBLE_EQ(m.bone_peak_force_N, 2.0);
  EXPECT_EQ(r.steps[0].record.outcome, StepOutcome::kForbiddenPuncture);
  EXPECT_EQ(r.steps[0].failure, "dura punctured (forbidden)");
  EXPECT_FALSE(r.score.passed);
  EXPECT_NE(
      std::find(r.score.reasons_failed.begin(), r.score.reasons_failed.end(), "step in: dura punctured (forbidden)"),
      r.score.reasons_failed.end());
  ASSERT_EQ(r.punctures.size(), 3u);
  EXPECT_EQ(r.punctures[0].layer, "skin");
  EXPECT_EQ(r.punctures[1].layer, "flavum");
  EXPECT_EQ(r.punctures[2].layer, "dura");
  EXPECT_DOUBLE_EQ(r.punctures[1].peak_force_N, 5.0);
}

}  // namespace
}  // namespace needle::training
