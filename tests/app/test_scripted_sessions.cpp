// The good and sloppy operator scripts of each shipped task, run as `needle-sim run --headless`
// runs them (the product's TaskSession: the simulated device through the haptic loop, recorded,
// scored, stored): the good one passes and scores higher; the sloppy one fails the pass threshold.
#include <gtest/gtest.h>

#include <iostream>

#include "haptics/sim/scenario.hpp"
#include "recorded_session.hpp"

namespace needle::test {
namespace {

std::string report(const training::SessionResult& r) {
  std::string out = "score " + std::to_string(r.score.total) + ";";
  for (const training::StepResult& s : r.steps) out += " " + s.id + "=" + training::step_outcome_name(s.record.outcome);
  for (const training::ScoreComponent& c : r.score.components)
    out += " " + c.name + ":" + std::to_string(c.value).substr(0, 4);
  for (const std::string& why : r.score.reasons_failed) out += "; " + why;
  return out;
}

class ScriptedSessions : public testing::TestWithParam<const char*> {};

TEST_P(ScriptedSessions, GoodPassesAndOutscoresSloppyWhichFails) {
  const std::filesystem::path dir = process_folder(output_dir() / "scripted_sessions" / GetParam());
  const RecordedSession good = record_session(dir / "sessions.db", {GetParam(), "good", "ana", true});
  const RecordedSession sloppy = record_session(dir / "sessions.db", {GetParam(), "sloppy", "bo", true});
  const training::Task task = training::load_task(source_dir() / "assets/tasks" / (std::string(GetParam()) + ".json"));
  const double pass_score = task.scoring.pass_score;
  EXPECT_TRUE(good.result.score.passed) << report(good.result);
  EXPECT_FALSE(sloppy.result.score.passed) << report(sloppy.result);
  EXPECT_LT(sloppy.result.score.total, pass_score) << report(sloppy.result);
  EXPECT_GT(good.result.score.total, sloppy.result.score.total + 10.0) << report(good.result) << "\n"
                                                                       << report(sloppy.result);
  EXPECT_NE(good.recording, sloppy.recording) << "two sessions of one task in one second keep two recordings";
  // The good run stays within the device's force with the margin docs/TASKS.md states (20 %), and the
  // device never holds its force back.
  const double limit = haptics::load_scenario(task.scenario.string()).device.force_limit_N;
  EXPECT_LE(good.result.overall.peak_hand_force_N, 0.8 * limit) << report(good.result);
  EXPECT_EQ(good.result.overall.force_limited_s, 0.0) << report(good.result);
  std::cout << GetParam() << " good: " << report(good.result) << "\n"
            << GetParam() << " sloppy: " << report(sloppy.result) << "\n";
}

INSTANTIATE_TEST_SUITE_P(ShippedTasks, ScriptedSessions,
                         testing::Values("rigid_sphere", "penetrable_sphere", "sphere_ultrasound", "layered_target",
                                         "epidural", "epidural_air"));

}  // namespace
}  // namespace needle::test
