// Task files: the shipped thesis tasks load and agree with the thesis geometry; every kind of
// mistake is an error naming the file and the JSON pointer.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <nlohmann/json.hpp>
#include <numbers>

#include "tests/support/test_paths.hpp"
#include "training/tasks/task.hpp"

namespace needle::training {
namespace {
namespace fs = std::filesystem;
using nlohmann::json;

const fs::path kTasks = test::source_dir() / "assets/tasks";
const Vec3 kCentre{0.4, 0.0, 0.0};  // thesis sphere, section 4.1
constexpr double kRadius = 0.1;

TEST(TaskFiles, RigidSphereFollowsTheThesisExperiment) {
  const Task t = load_task(kTasks / "rigid_sphere.json");
  ASSERT_EQ(t.steps.size(), 4u);
  EXPECT_EQ(t.steps[0].condition.type, ConditionType::kTipNear);
  EXPECT_EQ(t.steps[1].condition.type, ConditionType::kAxisAligned);
  EXPECT_EQ(t.steps[2].condition.type, ConditionType::kForceHeld);
  EXPECT_EQ(t.steps[3].condition.type, ConditionType::kWithdrawn);
  EXPECT_EQ(t.steps[0].condition.contact, ContactRequirement::kRigidSurface);
  EXPECT_TRUE(fs::is_regular_file(t.scene));
  EXPECT_TRUE(fs::is_regular_file(t.scenario));
  const Marker& contact = t.markers[t.marker_index("contact_point")];
  EXPECT_NEAR(distance(contact.position, kCentre), kRadius, 1e-9);  // on the surface
  const Marker& normal = t.markers[t.marker_index("sphere_normal")];
  EXPECT_EQ(normal.kind, MarkerKind::kSurfaceNormal);
  EXPECT_EQ(t.steps[1].guidance.normal_markers, t.marker_index("sphere_normal"));
  EXPECT_NEAR(t.steps[1].condition.within_rad, 6.0 * std::numbers::pi / 180.0, 1e-12);
}

TEST(TaskFiles, PenetrableSphereFollowsTheThesisExperiment) {
  const Task t = load_task(kTasks / "penetrable_sphere.json");
  ASSERT_EQ(t.steps.size(), 5u);
  const Marker& entry = t.markers[t.marker_index("entry")];
  const Marker& insertion = t.markers[t.marker_index("insertion_axis")];
  const Marker& pivot = t.markers[t.marker_index("pivot_axis")];
  const Marker& target = t.markers[t.marker_index("target")];
  EXPECT_NEAR(distance(entry.position, kCentre), kRadius, 1e-5);
  EXPECT_NEAR(norm(insertion.direction), 1.0, 1e-12);
  // The insertion axis points into the sphere along the inward normal at the entry.
  EXPECT_NEAR(dot(insertion.direction, (1.0 / kRadius) * (kCentre - entry.position)), 1.0, 1e-4);
  // The pivot happens at the tip after 3 cm of insertion, and turns the needle by 45 degrees.
  const Vec3 pivot_point = insertion.position + 0.03 * insertion.direction;
  EXPECT_NEAR(distance(pivot_point, pivot.position), 0.0, 1e-4);
  EXPECT_NEAR(angle_between(insertion.direction, pivot.direction), std::numbers::pi / 4, 1e-4);
  // The target lies on the pivot axis, 2 cm further, inside the sphere.
  EXPECT_NEAR(distance(pivot.position + 0.02 * pivot.direction, target.position), 0.0, 1e-9);
  EXPECT_LT(distance(target.position, kCentre), kRadius);
  EXPECT_DOUBLE_EQ(t.steps[2].tip_fixed_within_m, 0.005);
  EXPECT_EQ(t.steps[3].condition.contact, ContactRequirement::kTissue);  // target_reached implies tissue
  EXPECT_EQ(t.steps[1].guidance.depth_gauge, t.marker_index("insertion_axis"));
}

TEST(TaskFiles, NormalMarkersStandOnTheOutwardNormalAtTheContact) {
  const Task t = load_task(kTasks / "rigid_sphere.json");
  const Marker& sphere = t.markers[t.marker_index("sphere_normal")];
  const Vec3 tip{0.3448, 0.0, 0.0736};  // inside, on the ray through (-0.6, 0, 0.8)
  const auto points = normal_marker_positions(t, sphere, tip);
  for (int k = 0; k < 3; ++k) {
    const Vec3 expected{0.4 - 0.6 * (0.1 + 0.02 * (k + 1)), 0.0, 0.8 * (0.1 + 0.02 * (k + 1))};
    EXPECT_NEAR(distance(points[k], expected), 0.0, 1e-12) << k;
  }
  const Vec3 inward = planned_direction(sphere, tip);
  EXPECT_NEAR(distance(inward, Vec3{0.6, 0.0, -0.8}), 0.0, 1e-12);
}

// A small valid task, written next to the test output so that "../" paths resolve.
json valid_task() {
  return json::parse(R"({
    "name": "t", "scene": ")" +
                     (kTasks / "../scenes/thesis_sphere.json").string() + R"(",
    "markers": [{"name": "p", "point": [0, 0, 0]}, {"name": "a", "axis": {"origin": [0, 0, 0], "direction": [0, 0, 2]}}],
    "steps": [
      {"id": "s0", "instruction": "go", "condition": {"type": "tip_near", "marker": "p", "within_m": 0.01}},
      {"id": "s1", "instruction": "in", "condition": {"type": "depth_in_band", "marker": "a", "min": 0.01, "max": 0.02},
       "guidance": {"depth_gauge": "a"}}
    ]})");
}

fs::path write_task(const json& task, const std::string& name) {
  const fs::path dir = test::output_dir() / "tasks";
  fs::create_directories(dir);
  const fs::path file = dir / (name + ".json");
  std::ofstream(file) << task.dump(2);
  return file;
}

// Loading `task` fails with a message holding the file, the pointer and `what`.
void expect_error(const json& task, const std::string& name, const std::string& pointer, const std::string& what) {
  const fs::path file = write_task(task, name);
  try {
    load_task(file);
    ADD_FAILURE() << name << ": loaded without error";
  } catch (const TaskError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find(file.string() + ": " + pointer + ": "), std::string::npos) << message;
    EXPECT_NE(message.find(what), std::string::npos) << message;
  }
}

// A weights block with every weight 0 but these three (an absent key keeps its default).
json weights(double completion, double tip_error, double retries) {
  json w;
  for (const char* key :
       {"axis_deviation", "lateral_load", "peak_force", "force_steadiness", "path_efficiency", "smoothness", "time"})
    w[key] = 0;
  w["completion"] = completion, w["tip_error"] = tip_error, w["retries"] = retries;
  return w;
}

TEST(TaskFiles, TheSmallValidTaskLoads) {
  const Task t = load_task(write_task(valid_task(), "valid"));
  EXPECT_NEAR(t.markers[1].direction[2], 1.0, 1e-15);  // normalized
  EXPECT_DOUBLE_EQ(t.scoring.weights.completion, 30.0);
}

TEST(TaskFiles, ErrorsNameTheFileAndThePointer) {
  json j = valid_task();
  j["steps"][0]["condition"]["type"] = "juggle";
  expect_error(j, "unknown_type", "/steps/0/condition/type", "unknown step type \"juggle\"");

  j = valid_task();
  j["steps"][0]["condition"]["marker"] = "nowhere";
  expect_error(j, "unknown_marker", "/steps/0/condition/marker", "no marker named \"nowhere\"");

  j = valid_task();
  j["steps"][0]["condition"]["within_m"] = -0.01;
  expect_error(j, "negative_distance", "/steps/0/condition/within_m", "must be in (0, 1] m");

  j = valid_task();
  j["steps"][0]["condition"]["marker"] = "a";
  expect_error(j, "wrong_kind", "/steps/0/condition/marker", "is not a point");

  j = valid_task();
  j["steps"][1]["condition"]["max"] = 0.005;
  expect_error(j, "empty_band", "/steps/1/condition/max", "must be greater than min");

  j = valid_task();
  j["steps"][1]["condition"]["type"] = "force_held";
  j["steps"][1]["condition"].erase("marker");
  j["steps"][1].erase("guidance");
  expect_error(j, "force_without_hold", "/steps/1/condition/hold_s", "missing");

  j = valid_task();
  j["steps"][0]["guidance"] = {{"depth_gauge", "a"}};
  expect_error(j, "gauge_without_depth", "/steps/0/guidance/depth_gauge", "needs a depth_in_band");

  j = valid_task();
  j["steps"][0]["time_limit_s"] = "soon";
  expect_error(j, "string_time", "/steps/0/time_limit_s", "expected a number");

  j = valid_task();
  j["steps"][1]["id"] = "s0";
  expect_error(j, "duplicate_step", "/steps/1/id", "used twice");

  j = valid_task();
  j["markers"][1]["name"] = "p";
  expect_error(j, "duplicate_marker", "/markers/1/name", "used twice");

  j = valid_task();
  j["markers"][1]["axis"]["direction"] = {0, 0, 0};
  expect_error(j, "zero_axis", "/markers/1/axis/direction", "zero vector");

  j = valid_task();
  j["markers"][0]["axis"] = j["markers"][1]["axis"];
  expect_error(j, "two_kinds", "/markers/0", "exactly one of");

  j = valid_task();
  j["steps"][0]["colour"] = "red";
  expect_error(j, "unknown_key", "/steps/0/colour", "unknown key");

  j = valid_task();
  j["scene"] = "no_such_scene.json";
  expect_error(j, "missing_scene", "/scene", "file not found");

  j = valid_task();
  j["steps"] = json::array();
  expect_error(j, "no_steps", "/steps", "non-empty array");

  j = valid_task();
  j["scoring"] = {{"weights", weights(0, 0, 0)}};
  expect_error(j, "zero_weights", "/scoring/weights", "add up to 0");

  j = valid_task();
  j["scoring"] = {{"pass_score", 120}};
  expect_error(j, "pass_over_100", "/scoring/pass_score", "[0, 100]");

  j = valid_task();
  j["description"] = "two\nlines";
  expect_error(j, "two_line_description", "/description", "one line");

  j = valid_task();
  j["steps"][0]["condition"]["contact"] = "bone";
  expect_error(j, "bad_contact", "/steps/0/condition/contact", "expected any, free, rigid or tissue");
}

// A task on the layered block's scenario: its layers come from the scenario, in its order, and the
// layer conditions and forbidden layers name them.
json layered_task() {
  json j = valid_task();
  j["scenario"] = (kTasks / "../scenarios/tissue_block_layers.json").string();
  j["steps"][0]["condition"] = {{"type", "tip_in_layer"}, {"layer", "muscle"}, {"hold_s", 0.5}};
  j["steps"][0]["forbidden"] = {{"punctured", {"fat"}}, {"touched", {"bone"}}};
  j["steps"][1]["condition"] = {{"type", "punctured"}, {"layer", "skin"}};
  j["steps"][1].erase("guidance");
  return j;
}

TEST(TaskFiles, LayerConditionsAndForbiddenLayersNameTheScenariosLayers) {
  const Task t = load_task(write_task(layered_task(), "layered"));
  ASSERT_EQ(t.layers.size(), 4u);
  EXPECT_EQ(t.layers[0].name, "skin");
  EXPECT_EQ(t.layers[2].name, "muscle");
  EXPECT_FALSE(t.layers[2].rigid);
  EXPECT_TRUE(t.layers[3].rigid);
  EXPECT_EQ(t.steps[0].condition.type, ConditionType::kTipInLayer);
  EXPECT_EQ(t.steps[0].condition.layer, 2);
  EXPECT_EQ(t.steps[0].forbidden_punctures, 1u << 1);
  EXPECT_EQ(t.steps[0].forbidden_touches, 1u << 3);
  EXPECT_EQ(t.steps[1].condition.type, ConditionType::kPunctured);
  EXPECT_EQ(t.steps[1].condition.layer, 0);
  EXPECT_FALSE(t.hide_layer_names);

  json j = layered_task();
  j["steps"][0]["condition"]["layer"] = "musle";
  expect_error(
      j, "unknown_layer", "/steps/0/condition/layer",
      "no layer named \"musle\" in the scenario's tissue (its layers: \"skin\", \"fat\", \"muscle\", \"bone\")");
  j = layered_task();
  j["steps"][0]["condition"]["layer"] = "bone";
  expect_error(j, "bone_holds_no_tip", "/steps/0/condition/layer", "layer \"bone\" is rigid");
  j = layered_task();
  j["steps"][0]["forbidden"]["touched"] = {"fat"};
  expect_error(j, "touch_soft", "/steps/0/forbidden/touched/0", "layer \"fat\" is not rigid");
  j = layered_task();
  j["steps"][0]["forbidden"]["punctured"] = json::array();
  expect_error(j, "empty_forbidden", "/steps/0/forbidden/punctured", "non-empty array of layer names");
  j = layered_task();
  j["steps"][0]["forbidden"]["cut"] = {"fat"};
  expect_error(j, "forbidden_key", "/steps/0/forbidden/cut", "unknown key");
  j = layered_task();
  j["steps"][0]["condition"]["marker"] = "p";
  expect_error(j, "layer_with_marker", "/steps/0/condition/marker", "unknown key");
  j = layered_task();
  j["hide_layer_names"] = "yes";
  expect_error(j, "hide_not_bool", "/hide_layer_names", "expected true or false");
  j = layered_task();
  j.erase("scenario");
  expect_error(j, "no_layers", "/steps/0/condition/layer", "the task has no layered tissue");
  j = layered_task();
  j["scenario"] = (test::output_dir() / "tasks/not_a_scenario.json").string();
  std::ofstream(test::output_dir() / "tasks/not_a_scenario.json") << R"({"name": 3})";
  expect_error(j, "broken_scenario", "/scenario", "not_a_scenario.json: /name: expected a non-empty string");
}

// Names become file names and keys: a path, a NUL or 300 characters are refused; so are weights
// whose sum overflows (all 1e308: a stored score of 0) and time limits past the longest session.
TEST(TaskFiles, NamesWeightsAndLimitsThatWouldRunAwayAreErrors) {
  json j = valid_task();
  j["name"] = "../../../escaped_rec";
  expect_error(j, "path_name", "/name", "\"../../../escaped_rec\": a task name is 1 to 64 letters, digits, '_' or '-'");
  j["name"] = std::string(300, 'n');
  expect_error(j, "long_name", "/name", "a task name is 1 to 64");
  j["name"] = std::string("a\0b", 3);
  expect_error(j, "nul_name", "/name", "contains a NUL character");
  j = valid_task();
  j["title"] = std::string("Pivot\0 drill", 12);
  expect_error(j, "nul_title", "/title", "contains a NUL character");
  j["title"] = std::string(201, 't');
  expect_error(j, "long_title", "/title", "longer than 200 bytes");

  j = valid_task();
  json w = weights(1e308, 1e308, 1e308);
  j["scoring"] = {{"weights", w}};
  expect_error(j, "huge_weights", "/scoring/weights", "add up to more than a number can hold");
  w["completion"] = std::numeric_limits<double>::infinity();  // written by nlohmann as null: not a number
  j["scoring"] = {{"weights", w}};
  expect_error(j, "infinite_weight", "/scoring/weights/completion", "expected a number");

  j = valid_task();
  j["steps"][0]["time_limit_s"] = 1e9;
  expect_error(j, "endless_limit", "/steps/0/time_limit_s", "must be in (0, 1800] s");
}

TEST(TaskFiles, ASessionLastsAtMostItsStepsLimitsPlusAMarginOrThirtyMinutes) {
  Task t = load_task(kTasks / "penetrable_sphere.json");
  EXPECT_DOUBLE_EQ(session_time_bound_s(t), 15.0 + 20.0 + 30.0 + 20.0 + 20.0 + kTaskEndMargin_s);
  t.steps[2].time_limit_s = 0.0;  // one step without a limit: only the longest session bounds it
  EXPECT_DOUBLE_EQ(session_time_bound_s(t), 1800.0);
  for (Step& s : t.steps) s.time_limit_s = 1000.0;
  EXPECT_DOUBLE_EQ(session_time_bound_s(t), 1800.0);
}

TEST(TaskFiles, WeightsAreNormalizedToOneHundred) {
  json j = valid_task();
  j["scoring"] = {{"weights", weights(1, 1, 2)}};
  const Task t = load_task(write_task(j, "weights"));
  EXPECT_DOUBLE_EQ(t.scoring.weights.completion, 25.0);
  EXPECT_DOUBLE_EQ(t.scoring.weights.retries, 50.0);
}

json probe() {
  return json::parse(R"({"probe": {"position": [0.33, 0, 0.07], "direction": [0, 0, -2], "lateral": [1, 0, 0],
                                   "depth_m": 0.06, "width_m": 0.045, "frequency_MHz": 5, "slice_thickness_m": 0.003}})");
}

TEST(TaskFiles, AnUltrasoundProbeLoadsAndWeighsTheNeedlesVisibility) {
  json j = valid_task();
  j["ultrasound"] = probe();
  j["steps"][0]["tip_out_of_plane_max_s"] = 1.5;
  const Task t = load_task(write_task(j, "probe"));
  ASSERT_TRUE(t.ultrasound_probe.has_value());
  EXPECT_EQ(t.ultrasound_probe->direction, (Vec3{0, 0, -1}));  // normalized
  EXPECT_EQ(t.ultrasound_probe->depth_m, 0.06);
  EXPECT_EQ(t.ultrasound_probe->width_m, 0.045);
  EXPECT_EQ(t.ultrasound_probe->slice_thickness_m, 0.003);
  EXPECT_EQ(t.steps[0].tip_out_of_plane_max_s, 1.5);
  // The default 10 joins the other defaults' 100, and all are normalized to 100.
  EXPECT_DOUBLE_EQ(t.scoring.weights.needle_visibility, 1000.0 / 110.0);
  EXPECT_DOUBLE_EQ(t.scoring.weights.completion, 3000.0 / 110.0);
  // Without a probe it weighs nothing and the others keep their defaults.
  EXPECT_EQ(load_task(write_task(valid_task(), "no_probe")).scoring.weights.needle_visibility, 0.0);
}

TEST(TaskFiles, TheNeedlesVisibilityNeedsAProbe) {
  json j = valid_task();
  j["steps"][0]["tip_out_of_plane_max_s"] = 1.5;
  expect_error(j, "rule_without_probe", "/steps/0/tip_out_of_plane_max_s", "needs the task's ultrasound probe");
  j = valid_task();
  j["scoring"] = {{"weights", {{"needle_visibility", 5}}}};
  expect_error(j, "weight_without_probe", "/scoring/weights/needle_visibility", "needs the task's ultrasound probe");
  j = valid_task();
  j["ultrasound"] = probe();
  j["ultrasound"]["probe"]["lateral"] = {1, 0, 0.1};
  expect_error(j, "skewed_probe", "/ultrasound/probe/lateral", "must be perpendicular to direction");
  j["ultrasound"]["probe"]["lateral"] = {1, 0, 0};
  j["ultrasound"]["probe"]["slice_thickness_m"] = 0;
  expect_error(j, "thin_slice", "/ultrasound/probe/slice_thickness_m", "");
}

TEST(TaskFiles, ASectionPlaneLoadsNormalizedAndABadOneIsAnError) {
  json j = valid_task();
  j["section"] = {{"point", {0.33, 0.0, 0.05}}, {"normal", {0.0, -3.0, 0.0}}};
  const Task t = load_task(write_task(j, "section"));
  ASSERT_TRUE(t.section_plane.has_value());
  EXPECT_EQ(t.section_plane->point, (Vec3{0.33, 0.0, 0.05}));
  EXPECT_EQ(t.section_plane->normal, (Vec3{0.0, -1.0, 0.0}));  // normalized
  EXPECT_FALSE(load_task(write_task(valid_task(), "no_section")).section_plane.has_value());
  j["section"]["normal"] = {0, 0, 0};
  expect_error(j, "zero_normal", "/section/normal", "must not be the zero vector");
  j["section"] = {{"point", {0.33, 0.0, 0.05}}};
  expect_error(j, "no_normal", "/section/normal", "missing");
  j["section"] = {{"point", {0.33, 0.0}}, {"normal", {0, 1, 0}}};
  expect_error(j, "short_point", "/section/point", "expected an array of 3 numbers");
  j["section"] = {{"point", {0.33, 0.0, 0.05}}, {"normal", {0, 1, 0}}, {"mode", "cut"}};
  expect_error(j, "unknown_key", "/section/mode", "unknown key (allowed: point, normal)");
}

TEST(TaskFiles, UnreadableAndMalformedFilesNameTheFile) {
  EXPECT_THROW(
      {
        try {
          load_task("/nonexistent/task.json");
        } catch (const TaskError& e) {
          EXPECT_NE(std::string(e.what()).find("/nonexistent/task.json: /: file not found"), std::string::npos);
          throw;
        }
      },
      TaskError);
  const fs::path file = test::output_dir() / "tasks" / "broken.json";
  fs::create_directories(file.parent_path());
  std::ofstream(file) << "{\"name\": ";
  try {
    load_task(file);
    ADD_FAILURE() << "loaded";
  } catch (const TaskError& e) {
    EXPECT_NE(std::string(e.what()).find(file.string() + ": /: not valid JSON"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace needle::training
