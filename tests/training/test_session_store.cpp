// The session store: round trip, migration of a schema-1 file, a killed run, readers beside a
// writer.
#include <gtest/gtest.h>
#include <sqlite3.h>
#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <thread>

#include "training/scoring/metric_fields.hpp"
#include "training/sessions/session_store.hpp"
#include "tests/support/full_disk.hpp"
#include "tests/support/test_paths.hpp"

namespace needle::training {
namespace {
namespace fs = std::filesystem;

// A fresh database path for the running test.
fs::path fresh_db() {
  const fs::path dir = test::output_dir() / "sessions";
  fs::create_directories(dir);
  const fs::path file = dir / (std::string(testing::UnitTest::GetInstance()->current_test_info()->name()) + ".db");
  for (const char* suffix : {"", "-wal", "-shm"}) fs::remove(file.string() + suffix);
  return file;
}

Task small_task() {
  Task t;
  t.name = "pivot_drill";
  t.title = "Pivot drill";
  t.source = "/tasks/pivot_drill.json";
  return t;
}

// A result with two steps, NaN metrics where they do not apply, and a score breakdown.
SessionResult a_result() {
  SessionResult r;
  StepResult a{"insert", {StepOutcome::kCompleted, 0.5, 7.25}, {}};
  a.metrics.duration_s = 6.75, a.metrics.lateral_load_Ns = 1.125, a.metrics.path_length_m = 0.0625;
  a.metrics.withdrawals = 2, a.metrics.first_fault = 3;
  StepResult b{"pivot", {StepOutcome::kTipMoved, 7.25, 9.0}, {}};
  b.metrics.tip_error_m = 0.003, b.metrics.normalized_jerk = 123.5;
  r.steps = {a, b};
  r.overall = combine_metrics(r.steps);
  r.score.total = 61.5;
  r.score.passed = false;
  r.score.components = {{"completion", 0.5, 30.0}, {"tip_error", 0.7, 15.0}};
  r.finished = true;
  return r;
}

void expect_same_metrics(const Metrics& got, const Metrics& want) {
  for_each_metric(got, [&](const char* name, const auto& g) {
    for_each_metric(want, [&](const char* other, const auto& w) {
      if (std::string(name) != other) return;
      if constexpr (std::is_floating_point_v<std::decay_t<decltype(w)>>) {
        if (std::isnan(w))
          EXPECT_TRUE(std::isnan(g)) << name;
        else
          EXPECT_DOUBLE_EQ(g, w) << name;
      } else {
        EXPECT_EQ(g, w) << name;
      }
    });
  });
}

TEST(SessionStore, RoundTrip) {
  const fs::path file = fresh_db();
  SessionStore store(file);
  EXPECT_EQ(store.schema_version(), kSessionSchemaVersion);
  EXPECT_EQ(store.journal_mode(), "wal");
  const Task task = small_task();
  const int64_t first = store.begin_session("ana", task, "sim", "/runs/1/session.nsr");
  const int64_t second = store.begin_session("ben", task, "falcon", "");
  EXPECT_NE(first, second);
  const SessionResult result = a_result();
  store.finish_session(first, result);

  const std::vector<SessionInfo> list = store.sessions();
  ASSERT_EQ(list.size(), 2u);
  EXPECT_EQ(list[0].id, second);  // newest first
  EXPECT_FALSE(list[0].complete);
  EXPECT_EQ(list[0].ended_at, "");
  EXPECT_TRUE(list[1].complete);

  const StoredSession s = store.load(first);
  EXPECT_EQ(s.info.trainee, "ana");
  EXPECT_EQ(s.info.task, "pivot_drill");
  EXPECT_EQ(s.info.device, "sim");
  EXPECT_EQ(s.info.recording_path, "/runs/1/session.nsr");
  EXPECT_DOUBLE_EQ(s.info.score, 61.5);
  EXPECT_FALSE(s.info.passed);
  EXPECT_DOUBLE_EQ(s.info.duration_s, 6.75 + 0.0);
  EXPECT_EQ(s.info.started_at.size(), 20u);  // 2026-11-21T12:00:00Z
  EXPECT_EQ(s.info.started_at.back(), 'Z');
  EXPECT_GE(s.info.ended_at, s.info.started_at);
  ASSERT_EQ(s.steps.size(), 2u);
  for (size_t i = 0; i < 2; ++i) {
    EXPECT_EQ(s.steps[i].id, result.steps[i].id);
    EXPECT_EQ(s.steps[i].record.outcome, result.steps[i].record.outcome);
    EXPECT_DOUBLE_EQ(s.steps[i].record.start_s, result.steps[i].record.start_s);
    EXPECT_DOUBLE_EQ(s.steps[i].record.end_s, result.steps[i].record.end_s);
    expect_same_metrics(s.steps[i].metrics, result.steps[i].metrics);
  }
  expect_same_metrics(s.overall, result.overall);
  ASSERT_EQ(s.components.size(), 2u);
  EXPECT_EQ(s.components[1].name, "tip_error");
  EXPECT_DOUBLE_EQ(s.components[1].value, 0.7);
  EXPECT_DOUBLE_EQ(s.components[1].weight, 15.0);

  // The same trainee and task are not duplicated; the incomplete session has no results yet.
  store.begin_session("ana", task, "sim", "");
  EXPECT_EQ(store.sessions().size(), 3u);
  EXPECT_TRUE(store.load(second).steps.empty());
}

TEST(SessionStore, ErrorsNameTheFileAndWhatFailed) {
  const fs::path file = fresh_db();
  SessionStore store(file);
  const int64_t id = store.begin_session("ana", small_task(), "sim", "");
  store.finish_session(id, a_result());
  try {
    store.finish_session(id, a_result());
    ADD_FAILURE() << "finished twice";
  } catch (const SessionStoreError& e) {
    EXPECT_NE(std::string(e.what()).find(file.string() + ": finishing session " + std::to_string(id)),
              std::string::npos)
        << e.what();
  }
  EXPECT_EQ(store.load(id).steps.size(), 2u);  // the failed second finish changed nothing
  try {
    store.load(999);
    ADD_FAILURE() << "loaded a session that does not exist";
  } catch (const SessionStoreError& e) {
    EXPECT_NE(std::string(e.what()).find(file.string() + ": reading session 999: no such session"), std::string::npos)
        << e.what();
  }
  try {
    SessionStore nowhere("/nonexistent/dir/sessions.db");
    ADD_FAILURE() << "opened a file in a missing folder";
  } catch (const SessionStoreError& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent/dir/sessions.db: opening"), std::string::npos) << e.what();
  }
}

// Runs SQL on a raw connection (the tests' stand-in for an older program or another process).
void raw_exec(sqlite3* db, const std::string& sql) {
  char* message = nullptr;
  ASSERT_EQ(sqlite3_exec(db, sql.c_str(), nullptr, nullptr, &message), SQLITE_OK) << (message ? message : "");
}

TEST(SessionStore, MigratesASchemaOneFile) {
  const fs::path file = fresh_db();
  {
    SessionStore old(file, 1);
    EXPECT_EQ(old.schema_version(), 1);
  }
  // What a schema-1 program wrote: a finished session, one step, two metrics.
  sqlite3* db = nullptr;
  ASSERT_EQ(sqlite3_open(file.c_str(), &db), SQLITE_OK);
  raw_exec(db,
           "INSERT INTO trainees VALUES (1, 'old timer');"
           "INSERT INTO tasks VALUES (1, 'rigid_sphere', 'Rigid sphere', 'rigid_sphere.json');"
           "INSERT INTO sessions VALUES (1, 1, 1, '2026-01-02T03:04:05Z', '2026-01-02T03:05:00Z', 'complete',"
           "  82.5, 1, 55.0, '/runs/old.nsr');"
           "INSERT INTO step_results VALUES (1, 0, 'touch', 'completed', 0.0, 6.0);"
           "INSERT INTO metrics VALUES (1, 0, 'peak_force_N', 1.25), (1, -1, 'tip_error_m', NULL);");
  sqlite3_close(db);

  SessionStore store(file);
  EXPECT_EQ(store.schema_version(), 2);
  const StoredSession s = store.load(1);
  EXPECT_EQ(s.info.trainee, "old timer");
  EXPECT_EQ(s.info.device, "");  // schema 1 did not record it
  EXPECT_TRUE(s.info.complete);
  EXPECT_DOUBLE_EQ(s.info.score, 82.5);
  EXPECT_TRUE(s.info.passed);
  EXPECT_EQ(s.info.recording_path, "/runs/old.nsr");
  ASSERT_EQ(s.steps.size(), 1u);
  EXPECT_EQ(s.steps[0].record.outcome, StepOutcome::kCompleted);
  EXPECT_DOUBLE_EQ(s.steps[0].metrics.peak_force_N, 1.25);
  EXPECT_TRUE(std::isnan(s.overall.tip_error_m));
  EXPECT_TRUE(s.components.empty());
  // New sessions in the migrated file have what schema 2 added.
  const int64_t id = store.begin_session("old timer", small_task(), "mouse", "");
  store.finish_session(id, a_result());
  EXPECT_EQ(store.load(id).info.device, "mouse");
  EXPECT_EQ(store.load(id).components.size(), 2u);
}

TEST(SessionStore, RefusesAFileFromANewerProgram) {
  const fs::path file = fresh_db();
  { SessionStore store(file); }
  sqlite3* db = nullptr;
  ASSERT_EQ(sqlite3_open(file.c_str(), &db), SQLITE_OK);
  raw_exec(db, "PRAGMA user_version = 7");
  sqlite3_close(db);
  try {
    SessionStore store(file);
    ADD_FAILURE() << "opened a schema-7 file";
  } catch (const SessionStoreError& e) {
    EXPECT_NE(std::string(e.what()).find(file.string() + ": schema version 7 is newer"), std::string::npos) << e.what();
  }
}

TEST(SessionStore, AKilledRunLeavesAnIncompleteSessionAndAReadableFile) {
  const fs::path file = fresh_db();
  const pid_t child = fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    // The trainee's run: one session finished, the next started, then the process dies
    // without closing anything.
    SessionStore store(file);
    const int64_t done = store.begin_session("ana", small_task(), "sim", "/runs/a.nsr");
    store.finish_session(done, a_result());
    const int64_t dying = store.begin_session("ana", small_task(), "sim", "/runs/b.nsr");
    // Die in the middle of a write transaction: half of a finish, never committed.
    sqlite3* db = nullptr;
    sqlite3_open(file.c_str(), &db);
    sqlite3_exec(db,
                 ("BEGIN IMMEDIATE; INSERT INTO step_results VALUES (" + std::to_string(dying) +
                  ", 0, 'touch', 'completed', 0, 1)")
                     .c_str(),
                 nullptr, nullptr, nullptr);
    _exit(0);
  }
  int status = 0;
  ASSERT_EQ(waitpid(child, &status, 0), child);
  ASSERT_TRUE(WIFEXITED(status));
  ASSERT_EQ(WEXITSTATUS(status), 0);

  SessionStore store(file);
  const std::vector<SessionInfo> list = store.sessions();
  ASSERT_EQ(list.size(), 2u);
  EXPECT_FALSE(list[0].complete);
  EXPECT_EQ(list[0].recording_path, "/runs/b.nsr");
  EXPECT_TRUE(store.load(list[0].id).steps.empty());  // the uncommitted half is gone
  EXPECT_TRUE(list[1].complete);
  EXPECT_EQ(store.load(list[1].id).steps.size(), 2u);  // nothing already recorded is lost
  sqlite3* db = nullptr;
  ASSERT_EQ(sqlite3_open(file.c_str(), &db), SQLITE_OK);
  sqlite3_stmt* check = nullptr;
  ASSERT_EQ(sqlite3_prepare_v2(db, "PRAGMA integrity_check", -1, &check, nullptr), SQLITE_OK);
  ASSERT_EQ(sqlite3_step(check), SQLITE_ROW);
  EXPECT_STREQ(reinterpret_cast<const char*>(sqlite3_column_text(check, 0)), "ok");
  sqlite3_finalize(check);
  sqlite3_close(db);
}

TEST(SessionStore, AReaderIsNotBlockedByAnOpenWriteTransaction) {
  const fs::path file = fresh_db();
  SessionStore reader(file);
  const int64_t id = reader.begin_session("ana", small_task(), "sim", "");
  sqlite3* writer = nullptr;
  ASSERT_EQ(sqlite3_open(file.c_str(), &writer), SQLITE_OK);
  raw_exec(writer,
           "BEGIN IMMEDIATE; UPDATE sessions SET status = 'complete', score = 99 WHERE id = " + std::to_string(id));
  // The write transaction is open: the reader sees the last committed state, at once.
  EXPECT_FALSE(reader.load(id).info.complete);
  EXPECT_EQ(reader.sessions().size(), 1u);
  raw_exec(writer, "COMMIT");
  EXPECT_TRUE(reader.load(id).info.complete);
  EXPECT_DOUBLE_EQ(reader.load(id).info.score, 99.0);
  sqlite3_close(writer);
}

TEST(SessionStore, AWriterCommitsWhileAReaderHoldsASnapshot) {
  // With a rollback journal the commit would wait for the reader (and time out after 10 s).
  const fs::path file = fresh_db();
  SessionStore writer(file);
  const int64_t id = writer.begin_session("ana", small_task(), "sim", "");
  sqlite3* reader = nullptr;
  ASSERT_EQ(sqlite3_open(file.c_str(), &reader), SQLITE_OK);
  sqlite3_busy_timeout(reader, 0);
  raw_exec(reader, "BEGIN; SELECT count(*) FROM sessions");  // a read transaction stays open
  writer.finish_session(id, a_result());
  EXPECT_TRUE(writer.load(id).info.complete);
  sqlite3_stmt* status = nullptr;
  ASSERT_EQ(sqlite3_prepare_v2(reader, "SELECT status FROM sessions", -1, &status, nullptr), SQLITE_OK);
  ASSERT_EQ(sqlite3_step(status), SQLITE_ROW);
  EXPECT_STREQ(reinterpret_cast<const char*>(sqlite3_column_text(status, 0)), "incomplete");  // its snapshot
  sqlite3_finalize(status);
  raw_exec(reader, "COMMIT");
  sqlite3_close(reader);
}

TEST(SessionStore, ConcurrentReaderSeesWholeSessionsOnly) {
  const fs::path file = fresh_db();
  { SessionStore create(file); }
  constexpr int kSessions = 40;
  std::atomic<bool> writing{true};
  std::atomic<int> reads{0};
  std::string reader_error;
  std::thread writer_thread([&] {
    SessionStore writer(file);
    for (int i = 0; i < kSessions; ++i)
      writer.finish_session(writer.begin_session("w", small_task(), "sim", ""), a_result());
    writing = false;
  });
  std::thread reader_thread([&] {
    try {
      SessionStore reader(file);
      size_t seen = 0;
      do {
        const std::vector<SessionInfo> list = reader.sessions();
        if (list.size() < seen) reader_error = "the session count went down";
        seen = list.size();
        for (const SessionInfo& info : list) {
          const StoredSession s = reader.load(info.id);
          if (s.info.complete != (s.steps.size() == 2)) reader_error = "a session half written";
        }
        ++reads;
      } while (writing || reads < 2);
    } catch (const std::exception& e) {
      reader_error = e.what();
    }
  });
  writer_thread.join();
  reader_thread.join();
  EXPECT_EQ(reader_error, "");
  SessionStore check(file);
  EXPECT_EQ(check.sessions().size(), size_t(kSessions));
}

}  // namespace
}  // namespace needle::training

namespace needle::training {
namespace {

std::vector<char> bytes_of(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// A closed store of `sessions` finished sessions: everything in the main file, no WAL left.
void fill(const fs::path& file, int sessions) {
  SessionStore store(file);
  for (int k = 0; k < sessions; ++k) store.finish_session(store.begin_session("ana", small_task(), "sim", ""), a_result());
}

std::string open_error(const fs::path& file, bool read_only) {
  try {
    if (read_only)
      SessionStore(file, kReadOnly);
    else
      SessionStore{file};
  } catch (const SessionStoreError& e) {
    return e.what();
  }
  return "";
}

TEST(SessionStore, ADamagedOrCutDatabaseIsRefusedWhenOpenedAndLeftAsItIs) {
  const fs::path file = fresh_db();
  fill(file, 40);
  const std::vector<char> good = bytes_of(file);
  ASSERT_GT(good.size(), 4 * 4096u);
  const std::string damaged = file.string() + ": the session database is damaged (PRAGMA quick_check: ";

  std::vector<char> bad = good;  // the last page zeroed
  std::fill(bad.end() - 4096, bad.end(), 0);
  std::ofstream(file, std::ios::binary).write(bad.data(), std::streamsize(bad.size()));
  for (bool read_only : {false, true}) EXPECT_EQ(open_error(file, read_only).rfind(damaged, 0), 0u) << open_error(file, read_only);
  EXPECT_EQ(bytes_of(file), bad) << "a refused file is not touched";

  // Cut to half, as a copy that stopped short.
  std::ofstream(file, std::ios::binary).write(good.data(), std::streamsize(good.size() / 2));
  for (bool read_only : {false, true}) EXPECT_EQ(open_error(file, read_only).rfind(damaged, 0), 0u) << open_error(file, read_only);

  std::ofstream(file, std::ios::binary) << "not a database at all, but long enough to have a header........................";
  EXPECT_EQ(open_error(file, true).rfind(damaged, 0), 0u) << open_error(file, true);
}

TEST(SessionStore, ReadOnlyCreatesNothingAndNeedsNoWriteAccess) {
  const fs::path file = fresh_db();
  EXPECT_NE(open_error(file, true), "");
  EXPECT_FALSE(fs::exists(file));
  fill(file, 2);
  const test::ReadOnlyFolder folder(file.parent_path() / "read_only");
  const fs::path dir = folder.dir();
  fs::copy_file(file, dir / "sessions.db");
  ASSERT_EQ(folder.make_read_only(), "");
  EXPECT_NE(open_error(dir / "sessions.db", false), "") << "the folder is not read-only: the test shows nothing";
  SessionStore store(dir / "sessions.db", kReadOnly);
  ASSERT_EQ(store.sessions().size(), 2u);
  EXPECT_DOUBLE_EQ(store.load(1).info.score, a_result().score.total);
  EXPECT_THROW(store.begin_session("ana", small_task(), "sim", ""), SessionStoreError);
  EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 1) << "no -wal or -shm made";
}

}  // namespace
}  // namespace needle::training
