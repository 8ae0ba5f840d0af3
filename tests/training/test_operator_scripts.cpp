// How operator scripts are found and how bad ones are reported (training/tasks/scripted_operator.hpp).
// Their scores, through the product's session, are in tests/app/test_scripted_sessions.cpp.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "tests/support/test_paths.hpp"
#include "training/tasks/scripted_operator.hpp"

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

// The script is read strictly before it is merged into the task's scenario: its errors name the
// script file and the pointer in it, not the merged OUT/scenario.json.
std::string script_error(const std::string& name, const std::string& text) {
  const Task task = load_task(kTasks / "rigid_sphere.json");
  fs::create_directories(kOutput);
  const fs::path script = kOutput / (name + ".json");
  std::ofstream(script) << text;
  try {
    scenario_with_operator(task, script, kOutput / (name + "_merged.json"));
  } catch (const std::exception& e) {
    EXPECT_FALSE(fs::exists(kOutput / (name + "_merged.json"))) << "checked before anything is written";
    return e.what();
  }
  return "";
}

TEST(OperatorScriptFiles, ABadHandIsAnErrorNamingTheScriptAndThePointer) {
  const std::string waypoints =
      R"("waypoints": [{"t": 0, "p": [0.3, 0, 0.2], "dir": [1, 0, 0]}, {"t": 2, "p": [0.3, 0, 0.1], "dir": [1, 0, 0]}])";
  const std::string path = (kOutput / "").string();
  EXPECT_EQ(script_error("mass_negative", R"({"hand": {"mass_kg": -1, )" + waypoints + "}}"),
            path + "mass_negative.json: /hand/mass_kg: must be in (0, 10] kg, got -1");
  EXPECT_EQ(script_error("mass_zero", R"({"hand": {"mass_kg": 0, )" + waypoints + "}}"),
            path + "mass_zero.json: /hand/mass_kg: must be in (0, 10] kg, got 0");
  EXPECT_EQ(script_error("unknown_key", R"({"hand": {"speed": 3, )" + waypoints + "}}")
                .rfind(path + "unknown_key.json: /hand/speed: unknown key (allowed: mass_kg, ", 0),
            0u);
  EXPECT_EQ(script_error("unknown_top", R"({"hands": {}, "hand": {)" + waypoints + "}}")
                .rfind(path + "unknown_top.json: /hands: unknown key (allowed: description, hand)", 0),
            0u);
}

TEST(OperatorScriptFiles, WaypointTimesMustBeFiniteOrderedAndWithinTheLongestSession) {
  const std::string path = (kOutput / "").string();
  const std::string p = R"("p": [0.3, 0, 0.2], "dir": [1, 0, 0])";
  EXPECT_EQ(script_error("forever", R"({"hand": {"waypoints": [{"t": 0, )" + p + R"(}, {"t": 1e308, )" + p + "}]}}"),
            path + "forever.json: /hand/waypoints/1/t: must be in [0, 1800] s, got 1e+308");
  EXPECT_EQ(script_error("backwards", R"({"hand": {"waypoints": [{"t": 5, )" + p + R"(}, {"t": 2, )" + p + "}]}}"),
            path + "backwards.json: /hand/waypoints/1/t: must be after the waypoint before it (5.000000 s)");
  EXPECT_EQ(script_error("not_json", R"({"hand": )"),
            path + "not_json.json: /: not valid JSON: " +
                std::string("[json.exception.parse_error.101] parse error at line 1, "
                            "column 10: syntax error while parsing value - unexpected "
                            "end of input; expected '[', '{', or a literal"));
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
  ASSERT_EQ(merged.scene.tissue.layers().size(), 4u);
  EXPECT_EQ(merged.scene.tissue.layers()[3].name, "bone");
}

}  // namespace
}  // namespace needle::training
