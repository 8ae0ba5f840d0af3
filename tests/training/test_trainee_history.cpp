// What the start screen lists: the tasks of a folder (operator scripts left out, a broken file
// listed with its error) and a trainee's past per task, from sessions written by hand.
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <nlohmann/json.hpp>
#include <optional>

#include "tests/support/process_folder.hpp"
#include "tests/support/test_paths.hpp"
#include "training/sessions/trainee_history.hpp"
#include "training/tasks/task_catalog.hpp"

namespace needle::training {
namespace {

namespace fs = std::filesystem;

SessionInfo info(std::string trainee, std::string task, bool complete, double score) {
  SessionInfo s;
  s.trainee = std::move(trainee);
  s.task = std::move(task);
  s.complete = complete;
  s.score = score;
  return s;
}

TEST(TraineeHistory, TraineesMostRecentFirstAndTheLastAndBestScorePerTask) {
  const std::vector<SessionInfo> sessions = {
      // newest first, as the store lists them
      info("bo", "rigid_sphere", false, 0.0),         info("ana", "penetrable_sphere", true, 71.0),
      info("ana", "penetrable_sphere", false, 0.0),   info("ana", "penetrable_sphere", true, 85.0),
      info("Carla", "penetrable_sphere", true, 90.0), info("ana", "rigid_sphere", true, 60.0),
  };
  EXPECT_EQ(known_trainees(sessions), (std::vector<std::string>{"bo", "ana", "Carla"}));
  const std::map<std::string, TaskHistory> ana = task_history(sessions, "ana");
  ASSERT_EQ(ana.size(), 2u);
  EXPECT_EQ(ana.at("penetrable_sphere").last.score, 71.0) << "the newest complete one, not the best";
  EXPECT_EQ(ana.at("penetrable_sphere").best, 85.0);
  EXPECT_EQ(ana.at("penetrable_sphere").completed, 2) << "an incomplete session has no score";
  EXPECT_EQ(ana.at("rigid_sphere").completed, 1);
  EXPECT_TRUE(task_history(sessions, "bo").empty()) << "bo never finished a task";
  EXPECT_TRUE(task_history(sessions, "nobody").empty());
}

TEST(TaskCatalog, TheShippedTasksWithTheirTitlesAndDescriptionsAndNoScripts) {
  const std::vector<TaskEntry> tasks = find_tasks(test::source_dir() / "assets/tasks");
  // The thesis's tasks keep their place at the top, in their files' `order` (not the file names').
  ASSERT_EQ(tasks.size(), 10u);
  EXPECT_EQ(tasks[0].name, "penetrable_sphere");
  EXPECT_EQ(tasks[1].name, "rigid_sphere");
  EXPECT_EQ(tasks[2].name, "sphere_ultrasound");
  EXPECT_EQ(tasks[3].name, "layered_target");
  EXPECT_EQ(tasks[4].name, "epidural");
  EXPECT_EQ(tasks[5].name, "epidural_air");
  // Then the epidural on each shipped patient and on a random one (docs/TASKS.md, "Patients").
  EXPECT_EQ(tasks[6].name, "epidural_patient_bmi22");
  EXPECT_EQ(tasks[7].name, "epidural_patient_bmi30");
  EXPECT_EQ(tasks[8].name, "epidural_patient_bmi40");
  EXPECT_EQ(tasks[9].name, "epidural_patient_random");
  for (const TaskEntry& t : tasks) {
    EXPECT_TRUE(t.error.empty()) << t.error;
    EXPECT_FALSE(t.title.empty());
    EXPECT_FALSE(t.description.empty()) << t.name << ": the start screen shows a line about each shipped task";
  }
}

// A task file with `order`, at `dir / file`, on the penetrable sphere's scene.
void write_task(const fs::path& file, const std::string& name, std::optional<int> order) {
  nlohmann::json task = {{"name", name},
                         {"scene", (test::source_dir() / "assets/scenes/penetrable_sphere.json").string()},
                         {"markers", {{{"name", "p"}, {"point", {0.4, 0.0, 0.0}}}}},
                         {"steps",
                          {{{"id", "s"},
                            {"instruction", "x"},
                            {"condition", {{"type", "tip_near"}, {"marker", "p"}, {"within_m", 0.01}}}}}}};
  if (order) task["order"] = *order;
  std::ofstream(file) << task.dump();
}

TEST(TaskCatalog, TasksWithAnOrderComeFirstLowestFirstThenTheRestByFileName) {
  const fs::path dir = test::process_folder(test::output_dir() / "task_catalog_order");
  write_task(dir / "a.json", "a", std::nullopt);
  write_task(dir / "b.json", "b", 7);
  write_task(dir / "c.json", "c", 2);
  write_task(dir / "d.json", "d", 7);
  write_task(dir / "e.json", "e", std::nullopt);
  std::ofstream(dir / "0_broken.json") << "{\"name\": \"x\", \"order\": 1, \"colour\": 1}";
  std::vector<std::string> names;
  for (const TaskEntry& t : find_tasks(dir)) names.push_back(t.error.empty() ? t.name : "error");
  EXPECT_EQ(names, (std::vector<std::string>{"c", "b", "d", "error", "a", "e"}));
  write_task(dir / "f.json", "f", -1);
  const std::vector<TaskEntry> tasks = find_tasks(dir);
  const auto f = std::find_if(tasks.begin(), tasks.end(), [&](const TaskEntry& t) { return t.file == dir / "f.json"; });
  ASSERT_NE(f, tasks.end());
  EXPECT_NE(f->error.find("f.json: /order: expected a whole number from 0"), std::string::npos) << f->error;
}

TEST(TaskCatalog, ABrokenTaskIsListedWithItsErrorAndAMissingFolderIsAnError) {
  const fs::path dir = test::process_folder(test::output_dir() / "task_catalog");
  std::ofstream(dir / "a_broken.json") << "{\"name\": \"x\", \"colour\": 1}";
  std::ofstream(dir / "b_not_json.json") << "{";
  std::ofstream(dir / "c_script.json") << "{\"description\": \"an operator\", \"hand\": {}}";
  std::ofstream(dir / "notes.txt") << "not a task";
  const std::vector<TaskEntry> tasks = find_tasks(dir);
  ASSERT_EQ(tasks.size(), 2u);
  EXPECT_NE(tasks[0].error.find((dir / "a_broken.json").string() + ": /colour: unknown key"), std::string::npos)
      << tasks[0].error;
  EXPECT_NE(tasks[1].error.find("not valid JSON"), std::string::npos) << tasks[1].error;
  EXPECT_THROW(find_tasks(dir / "missing"), TaskError);
}

}  // namespace
}  // namespace needle::training
