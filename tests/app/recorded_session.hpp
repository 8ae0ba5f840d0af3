// A stored session with its recording, made by the product's own session object: a shipped task
// done by its scripted operator through the haptic loop, headless, recorded beside the database,
// scored and stored (app/task_session.hpp). Review, report and panel tests share it.
#pragma once

#include <filesystem>
#include <string>

#include "app/task_session.hpp"
#include "tests/support/process_folder.hpp"
#include "tests/support/test_paths.hpp"

namespace needle::test {

struct RecordedSessionSpec {
  std::string task = "penetrable_sphere";  // assets/tasks/<task>.json
  std::string operator_spec = "good";
  std::string trainee = "ana";
  bool finish = true;  // false: left incomplete, as a run that died
};

struct RecordedSession {
  int64_t id = 0;
  training::SessionResult result;   // what finish() scored; empty when left incomplete
  std::filesystem::path recording;  // absolute
  uint64_t samples = 0;
};

// Runs the task into `db` (its recording in `db`'s folder/recordings/, score.json and the
// scenario that ran in `db`'s folder/<trainee>_<operator>/).
inline RecordedSession record_session(const std::filesystem::path& db, const RecordedSessionSpec& spec = {}) {
  app::TaskSessionOptions options;
  options.task = source_dir() / "assets/tasks" / (spec.task + ".json");
  options.rig.operator_spec = spec.operator_spec;
  options.trainee = spec.trainee;
  options.db = db;
  options.out_dir = std::filesystem::absolute(db).parent_path() / (spec.trainee + "_" + spec.operator_spec);
  app::TaskSession session(options);
  session.run_offline([](size_t) {});
  RecordedSession out;
  out.id = session.session_id();
  out.recording = session.recording_path();
  if (spec.finish) out.result = *session.finish();
  out.samples = session.samples();
  return out;
}

}  // namespace needle::test
