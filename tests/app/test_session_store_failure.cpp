// A session whose store fails at its very end keeps its record: score.json is written (saying it
// was not stored) and the recording is kept, and the failure is said, naming both.
#include <gtest/gtest.h>
#include <sqlite3.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "haptics/recording/session_format.hpp"
#include "recorded_session.hpp"

namespace needle::test {
namespace {

namespace fs = std::filesystem;

TEST(SessionStoreFailure, ScoreJsonAndTheRecordingAreKeptWhenTheStoreFailsAtTheEnd) {
  const fs::path dir = process_folder(output_dir() / "store_failure");
  app::TaskSessionOptions options;
  options.task = source_dir() / "assets/tasks/rigid_sphere.json";
  options.trainee = "ana";
  options.db = dir / "sessions.db";
  options.out_dir = dir / "out";
  app::TaskSession session(options);
  session.run_offline([](size_t) {});
  {  // Another program breaks the store while the run goes on: finishing must write a table it dropped.
    sqlite3* db = nullptr;
    ASSERT_EQ(sqlite3_open(options.db.c_str(), &db), SQLITE_OK);
    EXPECT_EQ(sqlite3_exec(db, "DROP TABLE score_components", nullptr, nullptr, nullptr), SQLITE_OK)
        << sqlite3_errmsg(db);
    sqlite3_close(db);
  }
  std::string error;
  try {
    session.finish();
  } catch (const std::exception& e) {
    error = e.what();
  }
  const fs::path score_file = options.out_dir / "score.json";
  EXPECT_EQ(error.rfind("the session could not be stored: " + options.db.string() + ": finishing session 1", 0), 0u)
      << error;
  EXPECT_NE(error.find("its score is in " + score_file.string() + " and its recording is " +
                       session.recording_path().string()),
            std::string::npos)
      << error;
  ASSERT_TRUE(fs::is_regular_file(score_file));
  const nlohmann::json score = nlohmann::json::parse(std::ifstream(score_file));
  EXPECT_FALSE(score["stored"].get<bool>());
  EXPECT_TRUE(score["passed"].get<bool>());
  const haptics::Session recording = haptics::read_session(session.recording_path().string());
  EXPECT_TRUE(recording.end.closed);
  EXPECT_EQ(recording.records.size(), session.samples());
}

}  // namespace
}  // namespace needle::test
