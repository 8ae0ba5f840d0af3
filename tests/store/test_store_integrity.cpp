// A centre's records it can trust, on both engines: a finished session, its results and its
// recording refuse every change whoever asks through SQL (the schema's triggers); trainees and
// tasks are inserted, never changed by a run; a trainee's rename is logged; checks against the
// recording are kept and read back; a stored score no run stores is refused as damaged.
#include <gtest/gtest.h>

#include <cmath>

#include "store_engines.hpp"
#include "store_errors.hpp"
#include "tests/support/stored_sessions.hpp"

namespace needle::training {
namespace {
using test::a_result;
using test::small_task;

// Drops the triggers that keep a finished session final: what an owner who means to tamper can do
// (SQLite: drop them; PostgreSQL: disable them on its own tables).
void without_final_triggers(SqlConnection& c) {
  if (c.engine() == SqlEngine::kPostgres) {
    c.script("ALTER TABLE sessions DISABLE TRIGGER session_final", "");
    for (const char* t : {"step_results", "metrics", "score_components", "recording_chunks"})
      c.script(std::string("ALTER TABLE ") + t + " DISABLE TRIGGER session_rows_final", "");
    return;
  }
  for (const SqlRow& row :
       c.query("SELECT name FROM sqlite_master WHERE type = 'trigger' AND name LIKE '%final%'", {}, "").rows)
    c.script("DROP TRIGGER \"" + row.text(0) + "\"", "");
}

TEST_P(StoreEngines, AFinishedSessionIsFinalWhoeverAsks) {
  const std::string db = fresh();
  SessionStore store(db);
  const int64_t done = store.begin_session("ana", small_task(), "sim", "", "station-01");
  store.append_recording(done, 0, "abc");
  store.finish_session(done, a_result());
  const int64_t open = store.begin_session("ana", small_task(), "sim", "", "station-01");
  const std::string id = std::to_string(done);
  const std::unique_ptr<SqlConnection> owner = raw(db);  // the engine's most privileged user
  for (const std::string& sql : std::vector<std::string>{
           "UPDATE sessions SET score = 100, passed = 1 WHERE id = " + id + " AND status = 'complete'",
           "UPDATE sessions SET status = 'incomplete' WHERE id = " + id, "DELETE FROM sessions WHERE id = " + id,
           "INSERT INTO step_results VALUES (" + id + ", 9, 'forged', 'completed', 0, 1)",
           "UPDATE step_results SET outcome = 'completed' WHERE session_id = " + id,
           "DELETE FROM step_results WHERE session_id = " + id,
           "INSERT INTO metrics VALUES (" + id + ", -1, 'forged', 1)",
           "UPDATE metrics SET value = 0 WHERE session_id = " + id, "DELETE FROM metrics WHERE session_id = " + id,
           "INSERT INTO score_components VALUES (" + id + ", 9, 'forged', 1, 100)",
           "UPDATE score_components SET value = 1 WHERE session_id = " + id,
           "INSERT INTO recording_chunks VALUES (" + id + ", 3, " +
               (GetParam() == SqlEngine::kSqlite ? "x'00'" : "'\\x00'") + ", 0)",
           "UPDATE recording_chunks SET crc = 0 WHERE session_id = " + id,
           "DELETE FROM recording_chunks WHERE session_id = " + id,
           // Nor is a session begun complete, its score set in the same breath.
           "INSERT INTO sessions(trainee_id, task_id, started_at, status, score) VALUES (1, 1, 'x', 'complete', "
           "100)"}) {
    const std::string error = message_of([&] { owner->script(sql, ""); });
    EXPECT_TRUE(permission_error(error)) << sql << "\n" << error;
  }
  const StoredSession kept = store.load(done);
  EXPECT_DOUBLE_EQ(kept.info.score, a_result().score.total);
  EXPECT_TRUE(kept.info.complete);
  EXPECT_EQ(kept.steps.size(), 2u);
  EXPECT_EQ(kept.components.size(), 2u);
  EXPECT_EQ(store.recording(done), "abc");
  // An incomplete session still takes its rows, and is finished once.
  store.append_recording(open, 0, "de");
  store.finish_session(open, a_result());
  EXPECT_NE(message_of([&] { store.finish_session(open, a_result()); }).find("no incomplete session with that id"),
            std::string::npos);
  EXPECT_EQ(store.recording(open), "de");
}

TEST_P(StoreEngines, BeginningASessionLeavesItsTraineeAndTaskAsTheyAre) {
  const std::string db = fresh();
  SessionStore store(db);
  store.begin_session("ana", small_task(), "sim", "");
  Task renamed = small_task();
  renamed.title = "hijacked title";
  renamed.source = "/evil";
  store.begin_session("ana", renamed, "sim", "");
  const std::vector<SessionInfo> sessions = store.sessions();
  ASSERT_EQ(sessions.size(), 2u);
  for (const SessionInfo& s : sessions) {
    EXPECT_EQ(s.task_title, small_task().title);
    EXPECT_EQ(s.task_source, small_task().source);
  }
  EXPECT_EQ(raw(db)->query("SELECT count(*) FROM tasks", {}, "").rows[0].integer(0), 1);
}

// A schema-3 database's sessions, written the old way, read by this program and final from then on.
TEST_P(StoreEngines, MigratesASchemaThreeDatabase) {
  const std::string db = fresh();
  int64_t old_id = 0;
  {
    SessionStore old(db, 3);
    old_id = old.begin_session("ana", small_task(), "sim", "/runs/old.nrec", "station-01");
    old.append_recording(old_id, 0, "abc");
    old.finish_session(old_id, a_result());
    EXPECT_EQ(old.schema_version(), 3);
  }
  SessionStore store(db);
  EXPECT_EQ(store.schema_version(), kSessionSchemaVersion);
  const StoredSession s = store.load(old_id);
  EXPECT_DOUBLE_EQ(s.info.score, a_result().score.total);
  EXPECT_EQ(s.info.station, "station-01");
  EXPECT_EQ(s.steps.size(), 2u);
  EXPECT_FALSE(s.check);
  EXPECT_FALSE(store.sessions().at(0).check);
  EXPECT_EQ(verification(store.sessions().at(0)), Verification::kUnverified);
  EXPECT_EQ(store.recording(old_id), "abc");
  EXPECT_TRUE(permission_error(message_of(
      [&] { raw(db)->script("UPDATE sessions SET score = 100 WHERE id = " + std::to_string(old_id), ""); })));
}

TEST_P(StoreEngines, ATraineesRenameIsLogged) {
  const std::string db = fresh();
  SessionStore store(db);
  const int64_t id = store.begin_session("alise", small_task(), "sim", "");
  store.begin_session("ben", small_task(), "sim", "");
  EXPECT_TRUE(store.trainee_renames().empty());
  const TraineeRename r = store.rename_trainee("alise", "alice");
  EXPECT_EQ(r.old_name, "alise");
  EXPECT_EQ(r.new_name, "alice");
  EXPECT_EQ(r.renamed_at.size(), 20u) << r.renamed_at;                          // 2026-11-21T12:00:00Z
  EXPECT_EQ(r.renamed_by, GetParam() == SqlEngine::kPostgres ? "needle" : "");  // the login role; a file has none
  EXPECT_EQ(store.load(id).info.trainee, "alice");                              // the sessions follow the trainee
  ASSERT_EQ(store.trainee_renames().size(), 1u);
  EXPECT_EQ(store.trainee_renames()[0].old_name, "alise");
  // Refused: no such trainee, a name taken, an empty name; nothing logged for them.
  EXPECT_NE(message_of([&] { store.rename_trainee("nobody", "x"); }).find("no trainee named \"nobody\""),
            std::string::npos);
  EXPECT_NE(message_of([&] { store.rename_trainee("alice", "ben"); }).find("a trainee named \"ben\" exists already"),
            std::string::npos);
  EXPECT_NE(message_of([&] { store.rename_trainee("alice", ""); }).find("a name has 1 to 64 bytes"), std::string::npos);
  EXPECT_EQ(store.trainee_renames().size(), 1u);
  // A rename outside the program is logged too: the schema logs it, not the command.
  raw(db)->script("UPDATE trainees SET name = 'benedict' WHERE name = 'ben'", "");
  ASSERT_EQ(store.trainee_renames().size(), 2u);
  EXPECT_EQ(store.trainee_renames()[1].new_name, "benedict");
}

TEST_P(StoreEngines, ChecksAreKeptAndReadBackWithTheSession) {
  const std::string db = fresh();
  SessionStore store(db);
  const int64_t id = store.begin_session("ana", small_task(), "sim", "");
  store.finish_session(id, a_result());
  const StoredSession before = store.load(id);
  SessionCheck check{id,
                     CheckOutcome::kMismatch,
                     before.info.score,
                     result_digest(before),
                     "score: stored 61.5, replay 50",
                     "2026-11-22T10:00:00Z",
                     "dr-lee"};
  store.record_check(check);
  check.outcome = CheckOutcome::kVerified;
  check.detail = "";
  check.checked_at = "2026-11-23T10:00:00Z";
  store.record_check(check);
  const StoredSession after = store.load(id);
  ASSERT_TRUE(after.check);
  EXPECT_EQ(after.check->outcome, CheckOutcome::kVerified);  // the latest
  EXPECT_EQ(after.check->checked_at, "2026-11-23T10:00:00Z");
  EXPECT_EQ(after.check->digest, result_digest(before));
  EXPECT_EQ(after.check->checked_by,
            GetParam() == SqlEngine::kPostgres ? "needle" : "dr-lee");  // the role, whatever is said
  EXPECT_EQ(verification_status(after).verdict, Verification::kVerified);
  const SessionInfo listed = store.sessions().at(0);
  EXPECT_EQ(listed.check, CheckOutcome::kVerified);
  EXPECT_DOUBLE_EQ(listed.checked_score, before.info.score);
  EXPECT_EQ(verification(listed), Verification::kVerified);

  // The owner raises the score behind the triggers' back: the listing and the detail both say so.
  const std::unique_ptr<SqlConnection> owner = raw(db);
  without_final_triggers(*owner);
  owner->script("UPDATE sessions SET score = 99 WHERE id = " + std::to_string(id), "");
  EXPECT_EQ(verification(store.sessions().at(0)), Verification::kMismatch);
  EXPECT_EQ(verification_status(store.load(id)).verdict, Verification::kMismatch);
  // A metric changed, the score left alone: the listing cannot tell, the detail's digest can.
  owner->script(
      "UPDATE sessions SET score = " + std::to_string(before.info.score) + " WHERE id = " + std::to_string(id), "");
  owner->script("UPDATE metrics SET value = 0.5 WHERE name = 'path_length_m' AND step_index = 0", "");
  EXPECT_EQ(verification(store.sessions().at(0)), Verification::kVerified);
  const VerificationStatus status = verification_status(store.load(id));
  EXPECT_EQ(status.verdict, Verification::kMismatch);
  EXPECT_NE(status.line.find("changed since they were verified"), std::string::npos) << status.line;
}

TEST_P(StoreEngines, AStoredScoreNoRunStoresIsRefusedAsDamaged) {
  const std::string db = fresh();
  SessionStore store(db);
  const int64_t id = store.begin_session("ana", small_task(), "sim", "");
  store.finish_session(id, a_result());
  const std::unique_ptr<SqlConnection> owner = raw(db);
  without_final_triggers(*owner);
  for (const char* score : {"1e308", "-5", "100.5"}) {
    owner->script("UPDATE sessions SET score = " + std::string(score) + " WHERE id = " + std::to_string(id), "");
    const std::string error = message_of([&] { store.load(id); });
    EXPECT_NE(error.find(db + ": session " + std::to_string(id) + ": the stored score "), std::string::npos) << error;
    EXPECT_NE(error.find("outside what a run stores (0 to 100)"), std::string::npos) << error;
    EXPECT_THROW(store.load(id), StoredValueError);
  }
  owner->script("UPDATE sessions SET score = 100, duration_s = -1 WHERE id = " + std::to_string(id), "");
  EXPECT_NE(message_of([&] { store.load(id); }).find("the stored duration -1"), std::string::npos);
  owner->script("UPDATE sessions SET score = 0, duration_s = 0 WHERE id = " + std::to_string(id), "");
  EXPECT_EQ(message_of([&] { store.load(id); }), "") << "0 and 100 are scores a run stores";
}

}  // namespace
}  // namespace needle::training
