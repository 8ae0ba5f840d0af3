// A score pays only for what happened (docs/SCORING.md, "Score"): a component the task does not
// measure is not applicable and the others share its weight; one the run never reached earns
// nothing. The shipped tasks with hand-built runs, the weights worked out by hand.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <nlohmann/json.hpp>
#include <numbers>

#include "tests/support/test_paths.hpp"
#include "tool_states.hpp"
#include "training/scoring/session_scorer.hpp"
#include "training/sessions/session_export.hpp"

namespace needle::training {
namespace {
using haptics::ContactState;
using test::sample;
using test::state;

Task shipped(const char* name) {
  return load_task(needle::test::source_dir() / "assets/tasks" / (std::string(name) + ".json"));
}

std::map<std::string, ScoreComponent> by_name(const Score& s) {
  std::map<std::string, ScoreComponent> out;
  for (const ScoreComponent& c : s.components) out[c.name] = c;
  return out;
}

double sum_of_weights(const Score& s) {
  double sum = 0.0;
  for (const ScoreComponent& c : s.components) sum += c.weight;
  return sum;
}

// The tip moved from `from` to `to` in free space at constant speed over `seconds`, then held there
// until `end_s`, at 100 Hz; the needle along `axis_pitch` (test::state's pitch).
void free_run(SessionScorer& scorer, const Vec3& from, const Vec3& to, double seconds, double end_s, double pitch) {
  for (int k = 0; k * 0.01 <= end_s; ++k) {
    const double t = k * 0.01, u = std::min(1.0, t / seconds);
    scorer.feed(sample(state(t, from + u * (to - from), pitch)));
  }
}

// The penetrable sphere (no force_held step): force steadiness is not applicable, and the other
// nine components share its 5 points: each weighs its default times 100/95.
TEST(ScoreApplies, ARunThatNeverEntersTissueScoresNothingForTissueMetrics) {
  const Task task = shipped("penetrable_sphere");
  EXPECT_FALSE(task.scoring.measures.force_steadiness);
  EXPECT_TRUE(task.scoring.measures.lateral_load && task.scoring.measures.tip_error &&
              task.scoring.measures.axis_deviation);
  SessionScorer scorer(task);
  // Towards the entry (0.329, 0, 0.071) from 10 cm above it, stopping 3 cm short: never touching.
  free_run(scorer, {0.30, 0.0, 0.17}, {0.31, 0.0, 0.10}, 3.0, 110.0, std::numbers::pi / 4);
  const SessionResult r = scorer.result();
  ASSERT_TRUE(r.finished);
  EXPECT_EQ(r.overall.tissue_time_s, 0.0);
  EXPECT_EQ(r.overall.peak_needle_force_N, 0.0);
  const auto c = by_name(r.score);
  for (const char* name : {"lateral_load", "peak_force", "retries", "time"}) {
    EXPECT_EQ(c.at(name).status, ComponentStatus::kNotReached) << name;
    EXPECT_EQ(c.at(name).points(), 0.0) << name;
  }
  EXPECT_EQ(c.at("force_steadiness").status, ComponentStatus::kNotApplicable);
  EXPECT_EQ(c.at("force_steadiness").weight, 0.0);
  EXPECT_NEAR(c.at("completion").weight, 30.0 * 100.0 / 95.0, 1e-9);
  EXPECT_NEAR(c.at("lateral_load").weight, 10.0 * 100.0 / 95.0, 1e-9);  // kept: the task asks for it
  EXPECT_NEAR(sum_of_weights(r.score), 100.0, 1e-9);
  // The steps it reached still measure what it did: its movement, how it pointed, how far the tip ended.
  for (const char* name : {"completion", "tip_error", "axis_deviation", "path_efficiency", "smoothness"})
    EXPECT_EQ(c.at(name).status, ComponentStatus::kApplied) << name;
  EXPECT_EQ(c.at("tip_error").value, 0.0);  // 3 cm from the entry, 8 cm from the target: past the 8 mm reference
  double applied = 0.0;
  for (const ScoreComponent& x : r.score.components) applied += x.points();
  EXPECT_NEAR(r.score.total, applied, 1e-9);
  // Only the withdrawal completes (the tip is over 7 cm from the target): 1 of 5 steps, the path
  // straight (1) and the axis on the approach's line; the rest cannot add up to a pass.
  EXPECT_NEAR(c.at("completion").points(), 0.2 * 30.0 * 100.0 / 95.0, 1e-9);
  EXPECT_NEAR(c.at("path_efficiency").value, 1.0, 1e-9);
  EXPECT_LT(r.score.total, 35.0);
  EXPECT_FALSE(r.score.passed);
}

// The epidural's steps have no target: its tip error is not applicable and earns nothing; the
// layered defaults (10, 10, 5) and the syringe's (10) make 135 points, normalised to 100 on load,
// and without the tip error's 15 and the force steadiness's 5 (no force_held step) of those 135 the
// other components share 115: each its default x 100/115.
TEST(ScoreApplies, AnEpiduralWithoutATargetScoresNoTipErrorPoints) {
  const Task task = shipped("epidural");
  EXPECT_FALSE(task.scoring.measures.tip_error);
  EXPECT_FALSE(task.scoring.measures.force_steadiness);
  SessionScorer scorer(task);
  free_run(scorer, {0.33, 0.0, 0.12}, {0.33, 0.0, 0.0705}, 2.0, 3.0, std::numbers::pi / 2);
  const SessionResult r = scorer.result();
  EXPECT_TRUE(std::isnan(r.overall.tip_error_m));
  const auto c = by_name(r.score);
  EXPECT_EQ(c.at("tip_error").status, ComponentStatus::kNotApplicable);
  EXPECT_EQ(c.at("tip_error").weight, 0.0);
  EXPECT_EQ(c.at("tip_error").points(), 0.0);
  EXPECT_NEAR(c.at("completion").weight, 30.0 * 100.0 / 115.0, 1e-9);
  EXPECT_NEAR(c.at("overshoot").weight, 10.0 * 100.0 / 115.0, 1e-9);
  EXPECT_NEAR(c.at("loss_of_resistance").weight, 10.0 * 100.0 / 115.0, 1e-9);
  EXPECT_NEAR(sum_of_weights(r.score), 100.0, 1e-9);
  // Never in tissue, so no loss of resistance was found: the syringe's component is not reached.
  EXPECT_TRUE(std::isnan(r.overall.advance_after_loss_m));
  EXPECT_EQ(c.at("loss_of_resistance").status, ComponentStatus::kNotReached);
  EXPECT_EQ(c.at("loss_of_resistance").points(), 0.0);
}

// A layered run that tents the skin (the world pushes on the needle: the peak force applies) but
// never punctures it: overshoot, bone contacts and redirections are not reached, nor is the
// sideways load (never in tissue).
TEST(ScoreApplies, ALayeredRunThatNeverPuncturesEarnsNothingForOvershootAndBoneContacts) {
  const Task task = shipped("layered_target");
  SessionScorer scorer(task);
  for (int k = 0; k * 0.01 <= 100.0; ++k) {
    haptics::ToolSnapshot s = state(k * 0.01, {0.33, 0.0, 0.07 - std::min(k, 300) * 1e-5}, std::numbers::pi / 2);
    s.tissue.axial_force_N = k >= 100 ? 0.8 : 0.0;  // the skin's tent pushing back along the needle
    scorer.feed(sample(s));
  }
  const SessionResult r = scorer.result();
  EXPECT_EQ(r.overall.punctures, 0u);
  EXPECT_GT(r.overall.peak_needle_force_N, 0.0);
  const auto c = by_name(r.score);
  for (const char* name : {"overshoot", "bone_contacts", "redirections", "lateral_load", "time"}) {
    EXPECT_EQ(c.at(name).status, ComponentStatus::kNotReached) << name;
    EXPECT_EQ(c.at(name).points(), 0.0) << name;
  }
  EXPECT_EQ(c.at("peak_force").status, ComponentStatus::kApplied);
  EXPECT_EQ(c.at("peak_force").value, 1.0);  // 0.8 N at the hand, under the safe 3.3 N
  // No syringe in this task: its metrics did not apply, and no component pays for them.
  EXPECT_TRUE(std::isnan(r.overall.advance_after_loss_m));
  EXPECT_TRUE(std::isnan(r.overall.false_losses));
  EXPECT_EQ(c.count("loss_of_resistance"), 0u);
}

// Once a membrane gives way, the layered components apply and pay for what the run did.
TEST(ScoreApplies, APunctureMakesTheLayeredComponentsApply) {
  Metrics m;
  m.punctures = 2, m.bone_contacts = 1, m.overshoot_m = 0.004;
  EXPECT_TRUE(component_reached("bone_contacts", m, false));
  EXPECT_TRUE(component_reached("redirections", m, false));
  EXPECT_TRUE(component_reached("overshoot", m, false));
  m.punctures = 0, m.overshoot_m = kNotApplicable;
  EXPECT_TRUE(component_reached("bone_contacts", m, false));  // bone met without a puncture: it happened
  EXPECT_FALSE(component_reached("redirections", m, false));
  EXPECT_FALSE(component_reached("overshoot", m, false));
}

// The rigid sphere has no penetrable tissue: the sideways load is not applicable; its force band is
// the press step's, which a run that never got there did not reach.
TEST(ScoreApplies, TheRigidSphereHasNoLateralLoadAndAnUnreachedPressHasNoSteadiness) {
  const Task task = shipped("rigid_sphere");
  EXPECT_FALSE(task.scoring.measures.lateral_load);
  EXPECT_TRUE(task.scoring.measures.force_steadiness);
  SessionScorer scorer(task);
  free_run(scorer, {0.30, 0.0, 0.20}, {0.33, 0.0, 0.12}, 2.0, 80.0, std::numbers::pi / 2);
  const auto c = by_name(scorer.result().score);
  EXPECT_EQ(c.at("lateral_load").status, ComponentStatus::kNotApplicable);
  EXPECT_EQ(c.at("force_steadiness").status, ComponentStatus::kNotReached);
  EXPECT_NEAR(c.at("completion").weight, 30.0 * 100.0 / 90.0, 1e-9);
}

// score.json says which components applied: the keys it always had, and `applied` and `status`.
TEST(ScoreApplies, ScoreJsonSaysWhichComponentsApplied) {
  const Task task = shipped("epidural");
  SessionScorer scorer(task);
  free_run(scorer, {0.33, 0.0, 0.12}, {0.33, 0.0, 0.10}, 1.0, 2.0, std::numbers::pi / 2);
  const nlohmann::json j = result_json(scorer.result());
  std::map<std::string, nlohmann::json> c;
  for (const nlohmann::json& x : j["components"]) c[x["name"].get<std::string>()] = x;
  for (const char* key : {"name", "value", "weight", "points", "applied", "status"})
    EXPECT_TRUE(c["completion"].contains(key)) << key;
  EXPECT_EQ(c["tip_error"]["status"], "not_applicable");
  EXPECT_EQ(c["tip_error"]["applied"], false);
  EXPECT_EQ(c["lateral_load"]["status"], "not_reached");
  EXPECT_EQ(c["lateral_load"]["points"], 0.0);
  EXPECT_EQ(c["completion"]["status"], "applied");
  EXPECT_EQ(c["completion"]["applied"], true);
}

// The time in tissue, which decides whether the sideways load applies: the sum of the ticks' Δt in tissue.
TEST(ScoreApplies, TimeInTissueIsTheTicksInTissue) {
  const Task task = shipped("penetrable_sphere");
  SessionScorer scorer(task);
  for (int k = 0; k <= 300; ++k)
    scorer.feed(sample(
        state(k * 0.01, {0.33, 0.0, 0.07}, 0.0, k > 100 && k <= 250 ? ContactState::kTissue : ContactState::kFree)));
  EXPECT_NEAR(scorer.result().overall.tissue_time_s, 1.5, 1e-9);  // ticks 101..250, 0.01 s each
}

}  // namespace
}  // namespace needle::training
