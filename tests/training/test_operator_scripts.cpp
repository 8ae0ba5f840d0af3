// How operator scripts are found and how bad ones are reported (training/tasks/scripted_operator.hpp).
// Their scores, through the product's session, are in tests/app/test_scripted_sessions.cpp.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "training/tasks/scripted_operator.hpp"
#include "tests/support/test_paths.hpp"

namespace needle::training {
namespace {
namespace fs = std::filesystem;

const fs::path kTasks = test::source_dir() / "assets/tasks";
const fs::path kOutput = test::output_dir() / "operators";

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

namespace needle::training {
namespace {

// The merged scenario is written to the run's folder: a layered tissue's parameter files, named
// relative to the task's scenario, must still be found from there.
TEST(OperatorScriptFiles, ALayeredScenariosParameterFilesAreFoundFromTheMergedCopy) {
  Task task = load_task(kTasks / "penetrable_sphere.json");
  task.scenario = test::source_dir() / "assets/scenarios/tissue_block_layers.json";
  const haptics::Scenario merged =
      scenario_with_operator(task, kTasks / "penetrable_sphere_good.json", kOutput / "layered" / "scenario.json");
  ASSERT_EQ(merged.tissue.layers().size(), 4u);
  EXPECT_EQ(merged.tissue.layers()[3].name, "bone");
}

}  // namespace
}  // namespace needle::training
