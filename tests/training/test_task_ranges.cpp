// Every number of a task file has a range (training/tasks/task_limits.hpp, io/input_limits.hpp):
// a number past it, 1e300 or -1e300 or a hold longer than a session, is one line naming the file,
// the JSON pointer, the range and the value, never a run scored on nonsense. Every probe field
// is required, as docs/TASKS.md says. The expected ranges are written here as docs/TASKS.md states
// them.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "tests/support/test_paths.hpp"
#include "training/tasks/task.hpp"

namespace needle::training {
namespace {
namespace fs = std::filesystem;
using nlohmann::json;

// A shipped task with its scene and scenario made absolute, so that a copy loads from anywhere.
json shipped(const std::string& name) {
  const fs::path tasks = test::source_dir() / "assets/tasks";
  json t = json::parse(std::ifstream(tasks / (name + ".json")));
  for (const char* key : {"scene", "scenario", "patient"})
    if (t.contains(key) && t[key] != "random")
      t[key] = fs::weakly_canonical(tasks / t[key].get<std::string>()).string();
  return t;
}

// Where the running test writes its task (CTest runs each test as a process of its own).
fs::path task_file() {
  const fs::path dir = test::output_dir() / "task_ranges";
  fs::create_directories(dir);
  return dir / (std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()) + ".json");
}

// The error of loading `task` written as task_file(): "FILE: " and the rest, or "no error".
std::string error_of(const json& task) {
  const fs::path file = task_file();
  std::ofstream(file) << task.dump(1);
  try {
    load_task(file);
  } catch (const TaskError& e) {
    return e.what();
  }
  return "no error";
}

struct Case {
  const char* task;
  const char* pointer;
  double value;
  const char* range;  // as the error says it
};

TEST(TaskRanges, EveryNumberPastItsRangeNamesTheFileThePointerTheRangeAndTheValue) {
  const Case cases[] = {
      {"sphere_ultrasound", "/markers/0/point/0", 1e300, "[-10, 10] m"},
      {"sphere_ultrasound", "/markers/1/axis/origin/2", -1e300, "[-10, 10] m"},
      {"sphere_ultrasound", "/markers/1/axis/direction/0", 1e300, "[-1e+06, 1e+06]"},
      {"sphere_ultrasound", "/ultrasound/probe/position/0", 1e300, "[-10, 10] m"},
      {"sphere_ultrasound", "/ultrasound/probe/direction/2", -1e300, "[-1e+06, 1e+06]"},
      {"sphere_ultrasound", "/ultrasound/probe/depth_m", 1e300, "(0, 0.3] m"},
      {"sphere_ultrasound", "/ultrasound/probe/width_m", 1e300, "(0, 0.2] m"},
      {"sphere_ultrasound", "/ultrasound/probe/frequency_MHz", 1e300, "[1, 50] MHz"},
      {"sphere_ultrasound", "/ultrasound/probe/slice_thickness_m", 1e300, "(0, 0.02] m"},
      {"sphere_ultrasound", "/steps/0/condition/within_m", 1e300, "(0, 1] m"},
      {"sphere_ultrasound", "/steps/0/time_limit_s", 1e300, "(0, 1800] s"},
      {"sphere_ultrasound", "/steps/1/condition/min", 1e300, "[0, 0.2] m"},
      {"sphere_ultrasound", "/steps/1/condition/max", 1e300, "[0, 0.2] m"},
      {"sphere_ultrasound", "/steps/1/condition/hold_s", 3600, "[0, 1800] s"},  // longer than any session
      {"sphere_ultrasound", "/steps/1/tip_out_of_plane_max_s", 1e300, "(0, 1800] s"},
      {"sphere_ultrasound", "/scoring/safe_force_N", 1e300, "(0, 100] N"},
      {"sphere_ultrasound", "/scoring/pass_score", 1e300, "[0, 100]"},
      {"sphere_ultrasound", "/scoring/references/tip_error_m", 1e300, "(0, 1] m"},
      {"sphere_ultrasound", "/scoring/references/axis_deviation_deg", 1e300, "(0, 180] deg"},
      {"sphere_ultrasound", "/scoring/references/lateral_load_Ns", 1e300, "(0, 1000] N*s"},
      {"sphere_ultrasound", "/scoring/references/force_sd_N", 1e300, "(0, 100] N"},
      {"sphere_ultrasound", "/scoring/references/normalized_jerk", 1e300, "(0, 1e+12]"},
      {"sphere_ultrasound", "/scoring/references/time_s", 1e300, "(0, 1800] s"},
      {"sphere_ultrasound", "/scoring/references/overshoot_m", 1e300, "(0, 1] m"},
      {"rigid_sphere", "/normal_marker_spacing_m", 1e300, "(0, 0.1] m"},
      {"rigid_sphere", "/markers/1/surface_normal/centre/1", 1e300, "[-10, 10] m"},
      {"rigid_sphere", "/markers/1/surface_normal/radius", 1e300, "(0, 1] m"},
      {"rigid_sphere", "/steps/2/condition/min", -1e300, "[0, 100] N"},
      {"rigid_sphere", "/steps/2/condition/max", 1e300, "[0, 100] N"},
      {"penetrable_sphere", "/steps/2/tip_fixed_within_m", 1e300, "(0, 1] m"},
      {"epidural", "/section/point/0", 1e300, "[-10, 10] m"},
      {"epidural", "/section/normal/1", 1e300, "[-1e+06, 1e+06]"},
  };
  for (const Case& c : cases) {
    json t = shipped(c.task);
    if (std::string(c.pointer).rfind("/section/", 0) == 0)
      t["section"] = {{"point", {0.33, 0.0, 0.05}}, {"normal", {0.0, 1.0, 0.0}}};
    ASSERT_TRUE(t.contains(json::json_pointer(c.pointer).parent_pointer())) << c.pointer;
    t[json::json_pointer(c.pointer)] = c.value;
    char value[32];
    std::snprintf(value, sizeof value, "%g", c.value);
    EXPECT_EQ(error_of(t), task_file().string() + ": " + c.pointer + ": must be in " + c.range + ", got " + value)
        << c.pointer;
  }
}

TEST(TaskRanges, EveryProbeFieldIsRequired) {
  for (const char* key :
       {"position", "direction", "lateral", "depth_m", "width_m", "frequency_MHz", "slice_thickness_m"}) {
    json t = shipped("sphere_ultrasound");
    t["ultrasound"]["probe"].erase(key);
    EXPECT_EQ(error_of(t), task_file().string() + ": /ultrasound/probe/" + key + ": missing");
  }
}

// A task on a generated patient: its patient, its condition and its guidance are checked against the
// scenario (reading the task generates no patient).
TEST(TaskRanges, APatientTasksKeysAreChecked) {
  json t = shipped("epidural_patient_bmi22");
  t["steps"][1]["condition"]["interspace"] = "L6-L7";
  EXPECT_EQ(error_of(t),
            task_file().string() +
                ": /steps/1/condition/interspace: \"L6-L7\", expected L1-L2, L2-L3, L3-L4, L4-L5 or L5-S1");
  json on_block = shipped("layered_target");
  on_block["patient"] = "random";
  EXPECT_EQ(
      error_of(on_block),
      task_file().string() + ": /patient: the task's /scenario has no generated patient (tissue.patient) to replace");
  json landmarks = shipped("layered_target");
  landmarks["steps"][0]["guidance"]["landmarks"] = true;
  EXPECT_EQ(error_of(landmarks),
            task_file().string() +
                ": /steps/0/guidance/landmarks: landmarks need a generated patient (the task's /scenario has none)");
  json missing = shipped("epidural_patient_bmi22");
  missing["patient"] = "/nonexistent/patient.json";
  EXPECT_EQ(error_of(missing), task_file().string() + ": /patient: file not found: /nonexistent/patient.json");
}

// At most 64 markers and 64 steps: a task of 100,000 markers (5 MB) took half a minute to read
// before it was refused for a step's marker, and would draw each of them every frame.
TEST(TaskRanges, AtMost64MarkersAnd64Steps) {
  json task = shipped("penetrable_sphere");
  const size_t markers = task["markers"].size(), steps = task["steps"].size();
  for (size_t i = markers; i < 64; ++i)
    task["markers"].push_back({{"name", "m" + std::to_string(i)}, {"point", {0, 0, 0}}});
  for (size_t i = steps; i < 64; ++i) {
    task["steps"].push_back(task["steps"][0]);
    task["steps"].back()["id"] = "s" + std::to_string(i);
  }
  EXPECT_EQ(error_of(task), "no error");
  json more = task;
  more["markers"].push_back({{"name", "m64"}, {"point", {0, 0, 0}}});
  EXPECT_EQ(error_of(more), task_file().string() + ": /markers: expected an array of at most 64 markers");
  more = task;
  more["steps"].push_back(task["steps"][0]);
  more["steps"].back()["id"] = "s64";
  EXPECT_EQ(error_of(more), task_file().string() + ": /steps: expected a non-empty array of at most 64 steps");
}

TEST(TaskRanges, TheShippedTasksAreInsideEveryRange) {
  for (const char* name :
       {"rigid_sphere", "penetrable_sphere", "sphere_ultrasound", "layered_target", "epidural",
        "epidural_patient_bmi22", "epidural_patient_bmi30", "epidural_patient_bmi40", "epidural_patient_random"}) {
    EXPECT_EQ(error_of(shipped(name)), "no error") << name;
  }
}

// The syringe of a task (docs/TASKS.md, "Syringe") and the step that seeks its loss: each bad value
// one line naming the file and the pointer.
TEST(TaskRanges, TheSyringeAndTheStepThatSeeksItsLossAreCheckedOnLoad) {
  const std::string file = task_file().string() + ": ";
  json t = shipped("epidural");
  EXPECT_EQ(error_of(t), "no error");
  t["syringe"]["fluid"] = "water";
  EXPECT_EQ(error_of(t), file + "/syringe/fluid: expected \"saline\" or \"air\", got \"water\"");
  t = shipped("epidural");
  t["syringe"]["technique"] = "pumping";
  EXPECT_EQ(error_of(t), file + "/syringe/technique: expected \"continuous\" or \"intermittent\", got \"pumping\"");
  t = shipped("epidural");
  t["syringe"]["space"] = "upper lamina";  // bone holds no fluid
  EXPECT_EQ(error_of(t).rfind(file + "/syringe/space: no soft layer named \"upper lamina\"", 0), 0u) << error_of(t);
  t = shipped("epidural");
  t["syringe"].erase("space");
  EXPECT_EQ(error_of(t), file + "/syringe/space: missing");
  t = shipped("epidural");
  t["steps"][2]["stop_at_loss"]["within_m"] = 1e300;
  EXPECT_EQ(error_of(t), file + "/steps/2/stop_at_loss/within_m: must be in (0, 1] m, got 1e+300");
  t = shipped("epidural");
  t.erase("syringe");
  EXPECT_EQ(error_of(t), file + "/steps/2/stop_at_loss: needs the task's syringe (/syringe)");
  t = shipped(
      "layered_target");  // its tissue's parameter sets give their injection keys: any task on it may have a syringe
  t["syringe"] = {{"fluid", "saline"}, {"technique", "continuous"}, {"space", "fat"}};
  EXPECT_EQ(error_of(t), "no error");
}

}  // namespace
}  // namespace needle::training
