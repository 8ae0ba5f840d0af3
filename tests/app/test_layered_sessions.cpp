// The layered-tissue tasks (issue 14) done by their scripted operators as `needle-sim run
// --headless` does them (TaskSession: the simulated device through the haptic loop, recorded,
// scored, stored): the faults the sloppy operators make are named in the metrics and the reasons;
// the good runs complete every step (docs/TASKS.md, "Layered tasks: what the closed loop does").
#include <gtest/gtest.h>

#include <algorithm>
#include <iostream>

#include "recorded_session.hpp"

namespace needle::test {
namespace {

std::string report(const training::SessionResult& r) {
  std::string out = "score " + std::to_string(r.score.total) + ";";
  for (const training::StepResult& s : r.steps)
    out += " " + s.id + "=" + training::step_outcome_name(s.record.outcome) + (s.failure.empty() ? "" : "(" + s.failure + ")");
  const training::Metrics& m = r.overall;
  out += "; punctures " + std::to_string(m.punctures) + ", overshoot " + std::to_string(m.overshoot_m * 1e3) + " mm, bone " +
         std::to_string(m.bone_contacts) + ", redirections " + std::to_string(m.redirections) + ", forbidden " +
         std::to_string(m.forbidden_punctures);
  for (const training::PunctureResult& p : r.punctures)
    out += "; " + p.layer + " at " + std::to_string(p.depth_m * 1e3) + " mm, " + std::to_string(p.peak_force_N) + " N";
  for (const std::string& why : r.score.reasons_failed) out += "; " + why;
  return out;
}

bool says(const training::SessionResult& r, const std::string& reason) {
  return std::any_of(r.score.reasons_failed.begin(), r.score.reasons_failed.end(),
                     [&](const std::string& why) { return why.find(reason) != std::string::npos; });
}

TEST(LayeredSessions, LayeredTargetGoodCompletesEveryStepSloppyTouchesTheBoneAndFails) {
  const std::filesystem::path dir = process_folder(output_dir() / "layered_sessions" / "layered_target");
  const RecordedSession good = record_session(dir / "sessions.db", {"layered_target", "good", "ana", true});
  const RecordedSession sloppy = record_session(dir / "sessions.db", {"layered_target", "sloppy", "bo", true});
  std::cout << "layered_target good: " << report(good.result) << "\nlayered_target sloppy: " << report(sloppy.result) << "\n";
  // Every step completed, no bone touched.
  for (const training::StepResult& s : good.result.steps) EXPECT_EQ(s.record.outcome, training::StepOutcome::kCompleted) << s.id;
  ASSERT_GE(good.result.punctures.size(), 2u);
  EXPECT_EQ(good.result.punctures[0].layer, "skin");
  EXPECT_EQ(good.result.overall.bone_contacts, 0u);
  EXPECT_FALSE(sloppy.result.score.passed) << report(sloppy.result);
  EXPECT_GE(sloppy.result.overall.bone_contacts, 1u) << report(sloppy.result);
  EXPECT_TRUE(says(sloppy.result, "bone touched (forbidden)")) << report(sloppy.result);
  EXPECT_GT(good.result.score.total, sloppy.result.score.total) << report(good.result) << "\n" << report(sloppy.result);
}

TEST(LayeredSessions, EpiduralGoodStopsInTheEpiduralSpaceSloppyMeetsTheLamina) {
  const std::filesystem::path dir = process_folder(output_dir() / "layered_sessions" / "epidural");
  const RecordedSession good = record_session(dir / "sessions.db", {"epidural", "good", "ana", true});
  const RecordedSession sloppy = record_session(dir / "sessions.db", {"epidural", "sloppy", "bo", true});
  std::cout << "epidural good: " << report(good.result) << "\nepidural sloppy: " << report(sloppy.result) << "\n";
  // The good run reaches the loss of resistance: the flavum's puncture is the largest peak of the
  // approach.
  const auto& p = good.result.punctures;
  const auto flavum = std::find_if(p.begin(), p.end(), [](const auto& x) { return x.layer == "ligamentum flavum"; });
  ASSERT_NE(flavum, p.end()) << report(good.result);
  for (const training::PunctureResult& other : p)
    EXPECT_LE(other.peak_force_N, flavum->peak_force_N) << other.layer;
  EXPECT_FALSE(sloppy.result.score.passed) << report(sloppy.result);
  EXPECT_GE(sloppy.result.overall.bone_contacts, 1u) << report(sloppy.result);  // the upper lamina
  EXPECT_GT(good.result.score.total, sloppy.result.score.total) << report(good.result) << "\n" << report(sloppy.result);
  // The good run stops in the epidural space: every step completed, the dura whole (the spring along
  // the needle holds the virtual needle to the hand when the flavum gives way, docs/CONTROLLER.md).
  EXPECT_TRUE(good.result.score.passed) << report(good.result);
  for (const training::StepResult& s : good.result.steps) EXPECT_EQ(s.record.outcome, training::StepOutcome::kCompleted) << s.id;
  EXPECT_EQ(good.result.overall.forbidden_punctures, 0u) << report(good.result);
  EXPECT_TRUE(std::none_of(p.begin(), p.end(), [](const auto& x) { return x.layer == "dura"; })) << report(good.result);
}

}  // namespace
}  // namespace needle::test
