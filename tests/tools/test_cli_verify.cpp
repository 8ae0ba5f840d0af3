// needle-sim verify on a station's SQLite store, as an instructor meets it: a run's session is
// verified against its recording; a score the owner raised behind the triggers' back, a recording
// forged under valid checksums, a recording damaged, another session's recording: each is found,
// printed, exported, kept in the store for the review, and makes the exit code 1.
#include <gtest/gtest.h>

#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>

#include "app/recording_bytes.hpp"
#include "cli_process.hpp"
#include "tests/support/process_folder.hpp"
#include "training/sessions/session_store.hpp"
#include "training/sessions/sqlite_connection.hpp"

namespace needle::test {
namespace {

namespace fs = std::filesystem;

bool says(const ProcessResult& r, const std::string& text) { return r.output.find(text) != std::string::npos; }

std::string file_bytes(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// A scripted run of the rigid sphere (44 s of session, seconds of wall time) into `db`: its score.json.
nlohmann::json run_into(const fs::path& db, const fs::path& out, const std::string& trainee) {
  const ProcessResult r = run_needle_sim("run --headless --size 160x120 --trainee " + trainee + " --task " +
                                         quoted(source_dir() / "assets/tasks/rigid_sphere.json") + " --out " +
                                         quoted(out) + " --db " + quoted(db));
  EXPECT_EQ(r.exit_code, 0) << r.output;
  return nlohmann::json::parse(std::ifstream(out / "score.json"));
}

// The owner of an SQLite file can do anything with it: drop the triggers that keep a finished
// session final, then change what it likes.
void as_owner(const fs::path& db, const std::string& sql) {
  training::SqliteConnection owner(db.string(), false);
  for (const training::SqlRow& row :
       owner.query("SELECT name FROM sqlite_master WHERE type = 'trigger' AND name LIKE '%final%'", {}, "").rows)
    owner.script("DROP TRIGGER \"" + row.text(0) + "\"", "");
  owner.script(sql, "");
}

ProcessResult verify(const fs::path& db, const std::string& which, const fs::path& out) {
  return run_needle_sim("verify " + which + " --db " + quoted(db) + " --out " + quoted(out));
}

training::Verification listed(const fs::path& db, int64_t id) {
  training::SessionStore store(db.string(), training::kReadOnly);
  for (const training::SessionInfo& s : store.sessions())
    if (s.id == id) return training::verification(s);
  ADD_FAILURE() << "no session " << id;
  return training::Verification::kUnverified;
}

class CliVerify : public testing::Test {
 protected:
  void SetUp() override {
    dir_ =
        process_folder(test_output_dir("cli_verify") / testing::UnitTest::GetInstance()->current_test_info()->name());
    db_ = dir_ / "sessions.db";
    score_ = run_into(db_, dir_ / "run", "ana");
  }
  fs::path dir_, db_;
  nlohmann::json score_;
};

TEST_F(CliVerify, ARunsSessionIsVerifiedAndTheCheckKept) {
  EXPECT_EQ(listed(db_, 1), training::Verification::kUnverified);
  const ProcessResult r = verify(db_, "--all", dir_ / "v");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_TRUE(says(r, "session 1: verified")) << r.output;
  EXPECT_TRUE(says(r, "1 verified, 0 mismatch, 0 unverifiable of 1 complete session")) << r.output;
  EXPECT_TRUE(says(r, "the checks are kept in the store")) << r.output;
  const nlohmann::json report = nlohmann::json::parse(std::ifstream(dir_ / "v" / "verify.json"));
  EXPECT_EQ(report["verified"], 1);
  EXPECT_EQ(report["sessions"][0]["outcome"], "verified");
  EXPECT_GT(report["sessions_per_min"].get<double>(), 0.0);
  EXPECT_EQ(file_bytes(dir_ / "v" / "verify_mismatches.csv"), "session_id,outcome,what\n");
  EXPECT_EQ(listed(db_, 1), training::Verification::kVerified);
}

TEST_F(CliVerify, AScoreTheOwnerRaisedIsAMismatchNamingBothScores) {
  as_owner(db_, "UPDATE sessions SET score = 100, passed = 1 WHERE id = 1");
  const ProcessResult r = verify(db_, "--session 1", dir_ / "v");
  EXPECT_EQ(r.exit_code, 1) << r.output;
  char replayed[64];
  std::snprintf(replayed, sizeof replayed, "%.17g", score_["score"].get<double>());
  EXPECT_TRUE(says(r, "session 1: MISMATCH")) << r.output;
  EXPECT_TRUE(says(r, std::string("score: stored 100, replay ") + replayed)) << r.output;
  EXPECT_TRUE(says(r, "passed: stored yes, replay no") || score_["passed"].get<bool>()) << r.output;
  const std::string csv = file_bytes(dir_ / "v" / "verify_mismatches.csv");
  EXPECT_NE(csv.find(std::string("1,mismatch,\"score: stored 100, replay ") + replayed + "\""), std::string::npos)
      << csv;
  EXPECT_EQ(listed(db_, 1), training::Verification::kMismatch);
}

// The recording rewritten with a different hand (joint readings moved for 3 s) and every checksum
// made anew: it reads as a sound recording, and its replay is not what the store says was scored.
TEST_F(CliVerify, ARecordingForgedUnderValidChecksumsIsAMismatch) {
  const fs::path recording = score_["recording"].get<std::string>();
  haptics::Session session = haptics::read_session(recording.string());
  ASSERT_GT(session.records.size(), 20000u);
  for (size_t k = 8000; k < 11000; ++k) session.records[k].reading.joint_rad[0] += 0.05;
  std::ofstream(recording, std::ios::binary | std::ios::trunc) << app::encode_session(session);
  EXPECT_NO_THROW(haptics::read_session(recording.string())) << "the forgery passes every checksum";
  const ProcessResult r = verify(db_, "--all", dir_ / "v");
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_TRUE(says(r, "session 1: MISMATCH")) << r.output;
  EXPECT_TRUE(says(r, "metric ")) << r.output;
  EXPECT_EQ(listed(db_, 1), training::Verification::kMismatch);
}

TEST_F(CliVerify, ADamagedRecordingLeavesTheSessionUnverifiable) {
  const fs::path recording = score_["recording"].get<std::string>();
  std::string bytes = file_bytes(recording);
  bytes[bytes.size() / 2] ^= 0x01;  // one bit, its block's checksum not made anew
  std::ofstream(recording, std::ios::binary | std::ios::trunc) << bytes;
  const ProcessResult r = verify(db_, "--all", dir_ / "v");
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_TRUE(says(r, "session 1: unverifiable: " + recording.string() + ": block at byte")) << r.output;
  EXPECT_TRUE(says(r, "checksum mismatch (damaged)")) << r.output;
  EXPECT_EQ(listed(db_, 1), training::Verification::kUnverified);
}

TEST_F(CliVerify, AnotherSessionsRecordingIsAMismatchAndTheReportRefusesIt) {
  const nlohmann::json ben = run_into(db_, dir_ / "run_ben", "ben");
  as_owner(db_, "UPDATE sessions SET recording_path = '" + score_["recording"].get<std::string>() + "' WHERE id = 2");
  const ProcessResult r = verify(db_, "--session 2", dir_ / "v");
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_TRUE(says(r, "session 2: MISMATCH")) << r.output;
  EXPECT_TRUE(says(r, "the recording of another session (uid ")) << r.output;
  const ProcessResult report =
      run_needle_sim("report --session 2 --db " + quoted(db_) + " --out " + quoted(dir_ / "report"));
  EXPECT_EQ(report.exit_code, 1) << report.output;
  EXPECT_TRUE(says(report, score_["recording"].get<std::string>() + ": the recording of another session (uid "))
      << report.output;
  EXPECT_TRUE(says(report, "not of session 2 (uid ")) << report.output;
  EXPECT_FALSE(fs::exists(dir_ / "report" / "plot_force.png")) << "no plots of another session's recording";
}

TEST_F(CliVerify, WhatCannotBeVerifiedIsSaid) {
  EXPECT_EQ(run_needle_sim("verify --db " + quoted(db_)).exit_code, 2);
  EXPECT_EQ(run_needle_sim("verify --all --session 1 --db " + quoted(db_)).exit_code, 2);
  const ProcessResult none = verify(db_, "--session 99", dir_ / "v");
  EXPECT_EQ(none.exit_code, 1) << none.output;
  EXPECT_TRUE(says(none, db_.string() + ": no session 99")) << none.output;
  {
    training::SessionStore store(db_.string());
    training::Task task;
    task.name = "rigid_sphere";
    store.begin_session("cy", task, "sim", "");
  }
  const ProcessResult open = verify(db_, "--session 2", dir_ / "v");
  EXPECT_EQ(open.exit_code, 1) << open.output;
  EXPECT_TRUE(says(open, "session 2 is incomplete")) << open.output;
  const ProcessResult all = verify(db_, "--all", dir_ / "v");  // the incomplete one is not a complete session
  EXPECT_EQ(all.exit_code, 0) << all.output;
  EXPECT_TRUE(says(all, "of 1 complete session")) << all.output;
}

}  // namespace
}  // namespace needle::test
