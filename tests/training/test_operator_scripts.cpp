// The good and sloppy operator scripts of each shipped task, run through the closed-loop
// simulation of the task's scenario with the hand replaced by the script (training/tasks/
// scripted_operator.hpp) and scored: the good one passes and scores higher; the sloppy one
// fails the pass threshold. Also how scripts are found and how bad ones are reported.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "recorded_session.hpp"
#include "training/scoring/session_scorer.hpp"
#include "training/tasks/scripted_operator.hpp"
#include "tests/support/test_paths.hpp"

namespace needle::training {
namespace {
namespace fs = std::filesystem;

const fs::path kTasks = test::source_dir() / "assets/tasks";
const fs::path kOutput = test::output_dir() / "operators";

SessionResult run(const Task& task, const std::string& script) {
  const haptics::Scenario scenario = scenario_with_operator(task, operator_script_path(task, script),
                                                            kOutput / (task.name + "_" + script + ".json"));
  SessionScorer scorer(task);
  haptics::TickSample sample;
  haptics::run_closed_loop(scenario, false, [&](const haptics::TickRecord& r) {
    sample.state = test::snapshot_of(r);
    scorer.feed(sample);
  });
  return scorer.result();
}

std::string report(const SessionResult& r) {
  std::string out = "score " + std::to_string(r.score.total) + ";";
  for (const StepResult& s : r.steps) out += " " + s.id + "=" + step_outcome_name(s.record.outcome);
  for (const ScoreComponent& c : r.score.components) out += " " + c.name + ":" + std::to_string(c.value).substr(0, 4);
  for (const std::string& why : r.score.reasons_failed) out += "; " + why;
  return out;
}

class OperatorScripts : public testing::TestWithParam<const char*> {};

TEST_P(OperatorScripts, GoodPassesAndOutscoresSloppyWhichFails) {
  const Task task = load_task(kTasks / (std::string(GetParam()) + ".json"));
  const SessionResult good = run(task, "good");
  const SessionResult sloppy = run(task, "sloppy");
  EXPECT_TRUE(good.score.passed) << report(good);
  EXPECT_FALSE(sloppy.score.passed) << report(sloppy);
  EXPECT_LT(sloppy.score.total, task.scoring.pass_score) << report(sloppy);
  EXPECT_GT(good.score.total, sloppy.score.total + 10.0) << report(good) << "\n" << report(sloppy);
  std::cout << GetParam() << " good: " << report(good) << "\n" << GetParam() << " sloppy: " << report(sloppy) << "\n";
}

INSTANTIATE_TEST_SUITE_P(ShippedTasks, OperatorScripts, testing::Values("rigid_sphere", "penetrable_sphere"));

TEST(OperatorScriptFiles, GoodAndSloppyNameTheTasksOwnScriptsAnythingElseIsAFile) {
  const Task task = load_task(kTasks / "rigid_sphere.json");
  EXPECT_EQ(fs::canonical(operator_script_path(task, "good")), fs::canonical(kTasks / "rigid_sphere_good.json"));
  EXPECT_EQ(fs::canonical(operator_script_path(task, "sloppy")), fs::canonical(kTasks / "rigid_sphere_sloppy.json"));
  const fs::path other = kTasks / "penetrable_sphere_good.json";
  EXPECT_EQ(operator_script_path(task, other.string()), other);
  try {
    operator_script_path(task, "/nonexistent/script.json");
    ADD_FAILURE() << "found a script that does not exist";
  } catch (const TaskError& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent/script.json"), std::string::npos) << e.what();
  }
}

TEST(OperatorScriptFiles, AScriptWithoutWaypointsIsAnErrorNamingIt) {
  const Task task = load_task(kTasks / "rigid_sphere.json");
  fs::create_directories(kOutput);
  const fs::path script = kOutput / "no_waypoints.json";
  std::ofstream(script) << R"({"hand": {"waypoints": []}})";
  try {
    scenario_with_operator(task, script, kOutput / "no_waypoints_merged.json");
    ADD_FAILURE() << "ran a script without waypoints";
  } catch (const TaskError& e) {
    EXPECT_NE(std::string(e.what()).find(script.string() + ": /hand/waypoints"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace needle::training
