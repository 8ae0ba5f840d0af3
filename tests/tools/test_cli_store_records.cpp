// What needle-sim says of a station's store that lies or cannot be written: a stored score no run
// stores (1e308, -5) refused as damaged by report and report --cohort, naming the store and the
// session; a healthy store a run cannot write refused for what it is, not called damaged; a
// trainee's name corrected by an instructor's command, logged.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "cli_process.hpp"
#include "tests/support/full_disk.hpp"
#include "tests/support/process_folder.hpp"
#include "tests/support/stored_sessions.hpp"
#include "training/sessions/sqlite_connection.hpp"

namespace needle::test {
namespace {

namespace fs = std::filesystem;

bool says(const ProcessResult& r, const std::string& text) { return r.output.find(text) != std::string::npos; }

// A store of one finished session (a_result's, no recording), made without a run.
fs::path one_session(const std::string& name) {
  const fs::path dir = process_folder(test_output_dir("cli_store_records") / name);
  training::SessionStore store((dir / "sessions.db").string());
  store.finish_session(store.begin_session("ana", small_task(), "sim", ""), a_result());
  return dir / "sessions.db";
}

TEST(CliStoreRecords, AStoredScoreNoRunStoresIsRefusedByEveryReport) {
  const fs::path db = one_session("score");
  for (const char* score : {"1e308", "-5"}) {
    {  // the file's owner, past the triggers that keep a finished session final
      training::SqliteConnection owner(db.string(), false);
      owner.script("DROP TRIGGER IF EXISTS session_final_update", "");
      owner.script(std::string("UPDATE sessions SET score = ") + score + " WHERE id = 1", "");
    }
    for (const std::string& command : {"report --session 1", "report --cohort"}) {
      const ProcessResult r =
          run_needle_sim(command + " --db " + quoted(db) + " --out " + quoted(db.parent_path() / "out"));
      EXPECT_EQ(r.exit_code, 1) << command << "\n" << r.output;
      EXPECT_TRUE(says(r, db.string() + ": session 1: the stored score ")) << r.output;
      EXPECT_TRUE(says(r, "is outside what a run stores (0 to 100): the store is damaged or was altered")) << r.output;
    }
  }
  EXPECT_FALSE(fs::exists(db.parent_path() / "out" / "session_1.json")) << "nothing exported of it";
}

TEST(CliStoreRecords, AHealthyStoreARunCannotWriteIsNotCalledDamaged) {
  const fs::path db = one_session("read_only");
  const ReadOnlyFolder folder(db.parent_path() / "ro");
  fs::copy_file(db, folder.dir() / "sessions.db");
  ASSERT_EQ(folder.make_read_only(), "");
  const fs::path ro = folder.dir() / "sessions.db";
  const ProcessResult run =
      run_needle_sim("run --headless --size 160x120 --task " + quoted(source_dir() / "assets/tasks/rigid_sphere.json") +
                     " --out " + quoted(db.parent_path() / "run") + " --db " + quoted(ro));
  EXPECT_EQ(run.exit_code, 1) << run.output;
  EXPECT_TRUE(says(run, ro.string() + ": the session database cannot be written: ")) << run.output;
  EXPECT_FALSE(says(run, "restore a copy")) << run.output;
  EXPECT_FALSE(says(run, "simulated")) << "refused before the run\n" << run.output;
  const ProcessResult report =
      run_needle_sim("report --cohort --db " + quoted(ro) + " --out " + quoted(db.parent_path() / "c"));
  EXPECT_EQ(report.exit_code, 0) << report.output;
}

TEST(CliStoreRecords, AnInstructorCorrectsATraineesNameAndTheStoreLogsIt) {
  const fs::path db = one_session("rename");
  const ProcessResult r = run_needle_sim("trainee rename --from ana --to anna --db " + quoted(db));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_TRUE(says(r, "renamed trainee \"ana\" to \"anna\" in " + db.string() + " (logged at ")) << r.output;
  EXPECT_EQ(training::SessionStore(db.string(), training::kReadOnly).load(1).info.trainee, "anna");
  const ProcessResult log = run_needle_sim("trainee renames --db " + quoted(db));
  EXPECT_EQ(log.exit_code, 0) << log.output;
  EXPECT_TRUE(says(log, "\"ana\" -> \"anna\"")) << log.output;
  EXPECT_TRUE(says(log, "1 rename in ")) << log.output;
  const ProcessResult missing = run_needle_sim("trainee rename --from nobody --to x --db " + quoted(db));
  EXPECT_EQ(missing.exit_code, 1) << missing.output;
  EXPECT_TRUE(says(missing, "no trainee named \"nobody\"")) << missing.output;
  EXPECT_EQ(run_needle_sim("trainee rename --from anna --db " + quoted(db)).exit_code, 2);
  // A store that does not exist is named, and not made as a side effect.
  const fs::path none = db.parent_path() / "none.db";
  const ProcessResult no_db = run_needle_sim("trainee rename --from anna --to ana --db " + quoted(none));
  EXPECT_EQ(no_db.exit_code, 1) << no_db.output;
  EXPECT_TRUE(says(no_db, none.string() + ": no session database")) << no_db.output;
  EXPECT_FALSE(fs::exists(none));
}

}  // namespace
}  // namespace needle::test
