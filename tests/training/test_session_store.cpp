// The session store on SQLite: its journal, a killed run seen through SQLite's own integrity check,
// readers beside a writer, a damaged file, a read-only folder (both engines: tests/store/).
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

#include "tests/support/full_disk.hpp"
#include "tests/support/stored_sessions.hpp"
#include "tests/support/test_paths.hpp"
#include "training/scoring/metric_fields.hpp"
#include "training/sessions/session_store.hpp"
#include "training/sessions/sqlite_connection.hpp"

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

using test::a_result;
using test::small_task;

// SQLite's own: the journal, a file in a folder that does not exist. (What both engines do is in
// tests/store/, run on SQLite and PostgreSQL.)
TEST(SessionStore, AnSQLiteFileIsInWalModeAndAMissingFolderIsNamed) {
  const fs::path file = fresh_db();
  { SessionStore store(file); }
  EXPECT_EQ(SqliteConnection(file.string(), false).journal_mode(), "wal");
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
  for (int k = 0; k < sessions; ++k)
    store.finish_session(store.begin_session("ana", small_task(), "sim", ""), a_result());
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
  for (bool read_only : {false, true})
    EXPECT_EQ(open_error(file, read_only).rfind(damaged, 0), 0u) << open_error(file, read_only);
  EXPECT_EQ(bytes_of(file), bad) << "a refused file is not touched";

  // Cut to half, as a copy that stopped short.
  std::ofstream(file, std::ios::binary).write(good.data(), std::streamsize(good.size() / 2));
  for (bool read_only : {false, true})
    EXPECT_EQ(open_error(file, read_only).rfind(damaged, 0), 0u) << open_error(file, read_only);

  std::ofstream(file, std::ios::binary)
      << "not a database at all, but long enough to have a header........................";
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

// A healthy database where a run cannot write it (a read-only file system, or a folder where SQLite
// cannot make its -wal and -shm files) is never called damaged: that would send a user to replace
// good data. The error says what is wrong; a reader still reads it.
TEST(SessionStore, AHealthyDatabaseAWriterCannotWriteIsNotCalledDamaged) {
  const fs::path file = fresh_db();
  fill(file, 1);
  const test::ReadOnlyFolder folder(file.parent_path() / "read_only_writer");
  fs::copy_file(file, folder.dir() / "sessions.db");
  ASSERT_EQ(folder.make_read_only(), "");
  const std::string error = open_error(folder.dir() / "sessions.db", false);
  EXPECT_EQ(error.find("the session database is damaged"), std::string::npos) << error;
  EXPECT_EQ(error.find("restore a copy"), std::string::npos) << error;
  EXPECT_NE(error.find((folder.dir() / "sessions.db").string() + ": the session database cannot be written: "),
            std::string::npos)
      << error;
  const bool mounted = error.find("its file system is mounted read-only") != std::string::npos;
  EXPECT_TRUE(mounted || error.find("may not write") != std::string::npos) << error;
  EXPECT_NE(error.find("it is not damaged"), std::string::npos) << error;
  EXPECT_EQ(SessionStore(folder.dir() / "sessions.db", kReadOnly).sessions().size(), 1u);
}

}  // namespace
}  // namespace needle::training
