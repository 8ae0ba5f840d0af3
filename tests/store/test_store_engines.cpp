// The session store's behaviour, the same on both engines: every test here runs on an SQLite file
// and on a database of the test's own in the throwaway PostgreSQL cluster (with-postgres.sh).
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <thread>

#include "store_engines.hpp"
#include "tests/support/stored_sessions.hpp"
#include "tests/support/test_paths.hpp"
#include "tests/support/test_postgres.hpp"
#include "training/sessions/postgres_connection.hpp"
#include "training/sessions/session_sync.hpp"
#include "training/sessions/sqlite_connection.hpp"

namespace needle::training {
namespace {
namespace fs = std::filesystem;
using test::a_result;
using test::expect_same_metrics;
using test::small_task;

INSTANTIATE_TEST_SUITE_P(Engines, StoreEngines, testing::Values(SqlEngine::kSqlite, SqlEngine::kPostgres),
                         [](const auto& info) { return info.param == SqlEngine::kSqlite ? "SQLite" : "PostgreSQL"; });

TEST_P(StoreEngines, RoundTrip) {
  const std::string db = fresh();
  SessionStore store(db);
  EXPECT_EQ(store.engine(), GetParam());
  EXPECT_EQ(store.schema_version(), kSessionSchemaVersion);
  const Task task = small_task();
  const int64_t first = store.begin_session("ana", task, "sim", "/runs/1/session.nrec", "station-01");
  const int64_t second = store.begin_session("ben", task, "falcon", "", "station-02");
  EXPECT_NE(first, second);
  const SessionResult result = a_result();
  store.finish_session(first, result);

  const std::vector<SessionInfo> list = store.sessions();
  ASSERT_EQ(list.size(), 2u);
  EXPECT_EQ(list[0].id, second);  // newest first
  EXPECT_FALSE(list[0].complete);
  EXPECT_EQ(list[0].ended_at, "");
  EXPECT_EQ(list[0].station, "station-02");
  EXPECT_TRUE(list[1].complete);
  EXPECT_EQ(list[0].uid.size(), 32u);
  EXPECT_NE(list[0].uid, list[1].uid);

  const StoredSession s = store.load(first);
  EXPECT_EQ(s.info.trainee, "ana");
  EXPECT_EQ(s.info.task, "pivot_drill");
  EXPECT_EQ(s.info.task_title, "Pivot drill");
  EXPECT_EQ(s.info.device, "sim");
  EXPECT_EQ(s.info.station, "station-01");
  EXPECT_EQ(s.info.recording_path, "/runs/1/session.nrec");
  EXPECT_DOUBLE_EQ(s.info.score, 61.5);
  EXPECT_FALSE(s.info.passed);
  EXPECT_DOUBLE_EQ(s.info.duration_s, 6.75);
  EXPECT_EQ(s.info.started_at.size(), 20u);  // 2026-11-21T12:00:00Z
  EXPECT_GE(s.info.ended_at, s.info.started_at);
  ASSERT_EQ(s.steps.size(), 2u);
  for (size_t i = 0; i < 2; ++i) {
    EXPECT_EQ(s.steps[i].id, result.steps[i].id);
    EXPECT_EQ(s.steps[i].record.outcome, result.steps[i].record.outcome);
    EXPECT_EQ(s.steps[i].record.start_s, result.steps[i].record.start_s);  // bit for bit
    EXPECT_EQ(s.steps[i].record.end_s, result.steps[i].record.end_s);
    expect_same_metrics(s.steps[i].metrics, result.steps[i].metrics);
  }
  expect_same_metrics(s.overall, result.overall);
  ASSERT_EQ(s.components.size(), 2u);
  EXPECT_EQ(s.components[1].name, "tip_error");
  EXPECT_EQ(s.components[1].value, 0.7);
  EXPECT_EQ(s.components[1].weight, 15.0);
  // The same trainee and task are not duplicated; the incomplete session has no results yet.
  store.begin_session("ana", task, "sim", "");
  EXPECT_EQ(store.sessions().size(), 3u);
  EXPECT_TRUE(store.load(second).steps.empty());
  EXPECT_EQ(raw(db)->query("SELECT count(*) FROM trainees", {}, "").rows[0].integer(0), 2);
  EXPECT_EQ(store.find_uid(list[0].uid)->id, second);
  EXPECT_FALSE(store.find_uid("no such uid"));
}

// The store keeps each component's value and weight; whether it applied is read back as the score
// decided it: no weight, not in the task; no points and nothing of it reached (a_result never was
// in tissue), not reached; the rest applied (docs/SCORING.md, "Score").
TEST_P(StoreEngines, AComponentsStatusIsReadBackAsTheScoreDecidedIt) {
  const std::string db = fresh();
  SessionStore store(db);
  const int64_t id = store.begin_session("ana", small_task(), "sim", "");
  SessionResult result = a_result();
  result.score.components = {{"completion", 0.5, 30.0},
                             {"tip_error", 0.7, 15.0},
                             {"lateral_load", 0.0, 10.0, ComponentStatus::kNotReached},
                             {"force_steadiness", 0.0, 0.0, ComponentStatus::kNotApplicable}};
  store.finish_session(id, result);
  const StoredSession s = store.load(id);
  ASSERT_EQ(s.components.size(), 4u);
  for (size_t k = 0; k < 4; ++k)
    EXPECT_EQ(s.components[k].status, result.score.components[k].status) << s.components[k].name;
}

TEST_P(StoreEngines, ErrorsNameTheDatabaseAndWhatFailed) {
  const std::string db = fresh();
  SessionStore store(db);
  const int64_t id = store.begin_session("ana", small_task(), "sim", "");
  store.finish_session(id, a_result());
  try {
    store.finish_session(id, a_result());
    ADD_FAILURE() << "finished twice";
  } catch (const SessionStoreError& e) {
    EXPECT_NE(std::string(e.what()).find(db + ": finishing session " + std::to_string(id) +
                                         ": no incomplete session with that id"),
              std::string::npos)
        << e.what();
  }
  EXPECT_EQ(store.load(id).steps.size(), 2u);  // the failed second finish changed nothing
  try {
    store.load(999);
    ADD_FAILURE() << "loaded a session that does not exist";
  } catch (const SessionStoreError& e) {
    EXPECT_NE(std::string(e.what()).find(db + ": reading session 999: no such session"), std::string::npos) << e.what();
  }
}

TEST_P(StoreEngines, MigratesASchemaOneDatabase) {
  const std::string db = fresh();
  {
    SessionStore old(db, 1);
    EXPECT_EQ(old.schema_version(), 1);
  }
  // What a schema-1 program wrote: a finished session, one step, two metrics.
  raw(db)->script(
      "INSERT INTO trainees VALUES (1, 'old timer');"
      "INSERT INTO tasks VALUES (1, 'rigid_sphere', 'Rigid sphere', 'rigid_sphere.json');"
      "INSERT INTO sessions VALUES (1, 1, 1, '2026-01-02T03:04:05Z', '2026-01-02T03:05:00Z', 'complete',"
      "  82.5, 1, 55.0, '/runs/old.nsr');"
      "INSERT INTO step_results VALUES (1, 0, 'touch', 'completed', 0.0, 6.0);"
      "INSERT INTO metrics VALUES (1, 0, 'peak_force_N', 1.25), (1, -1, 'tip_error_m', NULL);",
      "writing as schema 1");
  SessionStore store(db);
  EXPECT_EQ(store.schema_version(), kSessionSchemaVersion);
  const StoredSession s = store.load(1);
  EXPECT_EQ(s.info.trainee, "old timer");
  EXPECT_EQ(s.info.device, "");   // schema 1 did not record it
  EXPECT_EQ(s.info.station, "");  // nor schema 2
  EXPECT_TRUE(s.info.complete);
  EXPECT_DOUBLE_EQ(s.info.score, 82.5);
  EXPECT_TRUE(s.info.passed);
  ASSERT_EQ(s.steps.size(), 1u);
  EXPECT_DOUBLE_EQ(s.steps[0].metrics.peak_force_N, 1.25);
  EXPECT_TRUE(std::isnan(s.overall.tip_error_m));
  EXPECT_TRUE(s.components.empty());
  // New sessions in the migrated database have what schemas 2 and 3 added. (PostgreSQL: the
  // identity column continues after the id an old program gave explicitly only when told; the
  // test gives it no clash by starting from an id of its own.)
  if (GetParam() == SqlEngine::kPostgres)
    raw(db)->script("SELECT setval(pg_get_serial_sequence('sessions', 'id'), 1)", "");
  if (GetParam() == SqlEngine::kPostgres)
    raw(db)->script("SELECT setval(pg_get_serial_sequence('trainees', 'id'), 1)", "");
  if (GetParam() == SqlEngine::kPostgres)
    raw(db)->script("SELECT setval(pg_get_serial_sequence('tasks', 'id'), 1)", "");
  const int64_t id = store.begin_session("old timer", small_task(), "mouse", "", "station-03");
  store.finish_session(id, a_result());
  EXPECT_EQ(store.load(id).info.device, "mouse");
  EXPECT_EQ(store.load(id).info.station, "station-03");
  EXPECT_EQ(store.load(id).components.size(), 2u);
}

TEST_P(StoreEngines, MigratesASchemaTwoDatabase) {
  const std::string db = fresh();
  int64_t old_id = 0;
  {
    SessionStore old(db, 2);  // writes as a schema-2 program did: no station, no uid
    old_id = old.begin_session("ana", small_task(), "falcon", "/runs/old.nrec", "ignored by schema 2");
    old.finish_session(old_id, a_result());
  }
  SessionStore store(db);
  EXPECT_EQ(store.schema_version(), kSessionSchemaVersion);
  const StoredSession s = store.load(old_id);
  EXPECT_EQ(s.info.device, "falcon");
  EXPECT_EQ(s.info.station, "");
  EXPECT_EQ(s.info.uid, "");
  EXPECT_EQ(s.components.size(), 2u);
  EXPECT_EQ(s.steps.size(), 2u);
  const int64_t id = store.begin_session("ana", small_task(), "sim", "", "station-01");
  EXPECT_EQ(store.load(id).info.station, "station-01");
  EXPECT_EQ(store.load(id).info.uid.size(), 32u);
  EXPECT_FALSE(store.recording(id));
}

TEST_P(StoreEngines, RefusesADatabaseFromANewerProgram) {
  const std::string db = fresh();
  { SessionStore store(db); }
  raw(db)->script(GetParam() == SqlEngine::kSqlite ? "PRAGMA user_version = 7" : "UPDATE needle_schema SET version = 7",
                  "");
  for (bool read_only : {false, true}) {
    try {
      if (read_only)
        SessionStore(db, kReadOnly);
      else
        SessionStore{db};
      ADD_FAILURE() << "opened a schema-7 database";
    } catch (const SessionStoreError& e) {
      EXPECT_NE(std::string(e.what()).find(db + ": schema version 7 is newer than this program's " +
                                           std::to_string(kSessionSchemaVersion)),
                std::string::npos)
          << e.what();
    }
  }
  EXPECT_EQ(raw(db)->query("SELECT count(*) FROM sessions", {}, "").rows[0].integer(0), 0);
}

TEST_P(StoreEngines, ReadOnlyWritesNothing) {
  const std::string db = fresh();
  {
    SessionStore store(db);
    store.begin_session("ana", small_task(), "sim", "");
  }
  SessionStore reader(db, kReadOnly);
  EXPECT_EQ(reader.sessions().size(), 1u);
  EXPECT_THROW(reader.begin_session("ben", small_task(), "sim", ""), SessionStoreError);
  EXPECT_EQ(reader.sessions().size(), 1u);
}

// A station that dies in the middle of finishing a session: what it committed stays, the half
// transaction is rolled back, the session stays incomplete.
TEST_P(StoreEngines, AKilledWriterLeavesAnIncompleteSession) {
  const std::string db = fresh();
  { SessionStore create(db); }
  const pid_t child = fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    SessionStore store(db);
    store.finish_session(store.begin_session("ana", small_task(), "sim", "/runs/a.nrec"), a_result());
    const int64_t dying = store.begin_session("ana", small_task(), "sim", "/runs/b.nrec");
    std::unique_ptr<SqlConnection> c = raw(db);
    c->begin(true, "dying");
    c->query("INSERT INTO step_results VALUES (?, 0, 'touch', 'completed', 0, 1)", {dying}, "dying");
    _exit(0);
  }
  int status = 0;
  ASSERT_EQ(waitpid(child, &status, 0), child);
  ASSERT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0);
  SessionStore store(db);
  const std::vector<SessionInfo> list = store.sessions();
  ASSERT_EQ(list.size(), 2u);
  EXPECT_FALSE(list[0].complete);
  EXPECT_TRUE(store.load(list[0].id).steps.empty());  // the uncommitted half is gone
  EXPECT_TRUE(list[1].complete);
  EXPECT_EQ(store.load(list[1].id).steps.size(), 2u);
}

TEST_P(StoreEngines, ConcurrentReaderSeesWholeSessionsOnly) {
  const std::string db = fresh();
  { SessionStore create(db); }
  constexpr int kSessions = 40;
  std::atomic<bool> writing{true};
  std::atomic<int> reads{0};
  std::string reader_error;
  std::thread writer_thread([&] {
    SessionStore writer(db);
    for (int i = 0; i < kSessions; ++i)
      writer.finish_session(writer.begin_session("w", small_task(), "sim", ""), a_result());
    writing = false;
  });
  std::thread reader_thread([&] {
    try {
      SessionStore reader(db, kReadOnly);
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
  EXPECT_EQ(SessionStore(db).sessions().size(), size_t(kSessions));
}

// Stations as processes writing at once: every session arrives once, whole, with every byte of
// its recording, and a reader meanwhile never sees one complete without its steps.
TEST_P(StoreEngines, ConcurrentStationsLoseNothing) {
  const std::string db = fresh();
  { SessionStore create(db); }
  constexpr int kStations = 4, kSessions = 8, kChunks = 5;
  const auto chunk = [](int station, int session, int k) {
    return std::string(size_t(300 + 7 * k), char('a' + station)) + std::to_string(session * 100 + k);
  };
  std::vector<pid_t> children;
  for (int station = 0; station < kStations; ++station) {
    const pid_t child = fork();
    ASSERT_GE(child, 0);
    if (child == 0) {
      try {
        SessionStore store(db);
        for (int n = 0; n < kSessions; ++n) {
          const int64_t id = store.begin_session("trainee " + std::to_string(n % 3), small_task(), "sim", "",
                                                 "station-" + std::to_string(station));
          int64_t offset = 0;
          for (int k = 0; k < kChunks; ++k) {
            const std::string bytes = chunk(station, n, k);
            store.append_recording(id, offset, bytes);
            offset += int64_t(bytes.size());
          }
          store.finish_session(id, a_result());
        }
        _exit(0);
      } catch (const std::exception& e) {
        std::fprintf(stderr, "station %d: %s\n", station, e.what());
        _exit(1);
      }
    }
    children.push_back(child);
  }
  std::string reader_error;
  {
    SessionStore reader(db, kReadOnly);
    for (int pass = 0; pass < 20; ++pass)
      for (const SessionInfo& info : reader.sessions())
        if (info.complete && reader.load(info.id).steps.size() != 2) reader_error = "a session half written";
  }
  for (const pid_t child : children) {
    int status = 0;
    ASSERT_EQ(waitpid(child, &status, 0), child);
    EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0);
  }
  EXPECT_EQ(reader_error, "");
  SessionStore store(db);
  const std::vector<SessionInfo> all = store.sessions();
  ASSERT_EQ(all.size(), size_t(kStations * kSessions));
  std::set<std::string> uids;
  std::map<std::string, int> per_station;
  for (const SessionInfo& info : all) {
    EXPECT_TRUE(info.complete);
    EXPECT_EQ(store.load(info.id).steps.size(), 2u);
    uids.insert(info.uid);
    ++per_station[info.station];
    const int station = info.station.back() - '0';
    // Which of its station's sessions it is: its recording's first chunk says.
    const std::optional<std::string> bytes = store.recording(info.id);
    ASSERT_TRUE(bytes);
    const int n = std::stoi(bytes->substr(300, bytes->find('a' + station, 300) - 300)) / 100;
    std::string want;
    for (int k = 0; k < kChunks; ++k) want += chunk(station, n, k);
    EXPECT_EQ(*bytes, want) << info.station << " session " << n;
  }
  EXPECT_EQ(uids.size(), all.size());
  for (int station = 0; station < kStations; ++station)
    EXPECT_EQ(per_station["station-" + std::to_string(station)], kSessions);
}

TEST_P(StoreEngines, ARecordingIsStoredInChunksAndCheckedWhenRead) {
  const std::string db = fresh();
  SessionStore store(db);
  const int64_t id = store.begin_session("ana", small_task(), "sim", "");
  EXPECT_FALSE(store.recording(id));
  std::string all;
  for (int k = 0; k < 3; ++k) {
    std::string bytes(size_t(1000 + k), '\0');
    for (size_t i = 0; i < bytes.size(); ++i)
      bytes[i] = char((i * 131 + size_t(k)) & 0xFF);  // every byte value, NULs too
    EXPECT_EQ(store.recording_bytes(id), int64_t(all.size()));
    store.append_recording(id, int64_t(all.size()), bytes);
    all += bytes;
  }
  EXPECT_EQ(store.recording(id), all);
  // One byte changed in the middle chunk: its checksum says so, naming the chunk.
  const std::string flip =
      GetParam() == SqlEngine::kSqlite
          ? "UPDATE recording_chunks SET bytes = substr(bytes, 1, 9) || x'FF' || substr(bytes, 11) "
            "WHERE byte_offset = 1000"
          : "UPDATE recording_chunks SET bytes = set_byte(bytes, 9, 255) WHERE byte_offset = 1000";
  raw(db)->script(flip, "");
  try {
    store.recording(id);
    ADD_FAILURE() << "a damaged chunk was read";
  } catch (const SessionStoreError& e) {
    EXPECT_NE(std::string(e.what()).find(": reading the recording of session " + std::to_string(id) +
                                         ": chunk at byte 1000: checksum mismatch"),
              std::string::npos)
        << e.what();
  }
  raw(db)->script("DELETE FROM recording_chunks WHERE byte_offset = 1000", "");
  try {
    store.recording(id);
    ADD_FAILURE() << "a recording with a chunk missing was read";
  } catch (const SessionStoreError& e) {
    EXPECT_NE(std::string(e.what()).find("chunk at byte 2001, expected 1000"), std::string::npos) << e.what();
  }
}

// Names are values, never SQL: quotes, a statement's end, placeholders, NUL-free binary-ish UTF-8.
TEST_P(StoreEngines, HostileNamesAreStoredAsTheyAre) {
  const std::string db = fresh();
  SessionStore store(db);
  const std::vector<std::string> names = {"Robert'); DROP TABLE sessions;--", "\"quoted\" ? $1 $2 %s %n",
                                          "O'Brien \\ back\\slash", "名前 – ümlaut ☃", std::string(200, '?')};
  for (const std::string& name : names) {
    Task task = small_task();
    task.name = name + " task";
    task.title = name;
    task.source = name;
    const int64_t id = store.begin_session(name, task, name, name, name);
    store.finish_session(id, a_result());
    const StoredSession s = store.load(id);
    EXPECT_EQ(s.info.trainee, name);
    EXPECT_EQ(s.info.task, task.name);
    EXPECT_EQ(s.info.task_title, name);
    EXPECT_EQ(s.info.device, name);
    EXPECT_EQ(s.info.recording_path, name);
    EXPECT_EQ(s.info.station, name);
  }
  EXPECT_EQ(store.sessions().size(), names.size());  // the sessions table is there, with each
}

// Sync: a session kept on the station is sent once, by its uid, also after a run that reached the
// server half-way (the session begun, part of its recording sent), and sending again adds nothing.
TEST_P(StoreEngines, SyncSendsAKeptSessionOnceByItsUid) {
  const fs::path dir = test_folder();
  const std::string server = fresh();
  const fs::path station_file = dir / "station.db";
  const fs::path recording = dir / "recordings" / "a.nrec";
  fs::create_directories(recording.parent_path());
  std::string bytes(5000, '\0');
  for (size_t i = 0; i < bytes.size(); ++i) bytes[i] = char(i * 7);
  std::ofstream(recording, std::ios::binary).write(bytes.data(), std::streamsize(bytes.size()));

  SessionStore station(station_file.string());
  SessionStore remote(server);
  // Two sessions: one the server never saw, one it saw begin with 1200 bytes of its recording.
  NewSession half{
      "ana",        "pivot_drill",     "Pivot drill",         "/tasks/pivot_drill.json", "sim", "recordings/a.nrec",
      "station-07", new_session_uid(), "2026-11-20T10:00:00Z"};
  const int64_t remote_half = remote.begin_session(half);
  remote.append_recording(remote_half, 0, bytes.substr(0, 1200));
  NewSession unseen = half;
  unseen.uid = new_session_uid();
  unseen.started_at = "2026-11-20T11:00:00Z";
  for (const NewSession& n : {half, unseen}) {
    const int64_t id = station.begin_session(n);
    station.finish_session(id, a_result(), "2026-11-20T12:00:00Z");
    station.keep_for_server(id, remote.name());
  }
  ASSERT_EQ(station.outbox().size(), 2u);

  const SyncReport first = sync_outbox(station, station_file, remote);
  EXPECT_EQ(first.sent.size(), 2u);
  EXPECT_TRUE(first.failed.empty()) << first.failed.front();
  EXPECT_TRUE(station.outbox().empty());
  // Kept again (a sync that died after sending, before marking): sending twice adds nothing.
  for (const SessionInfo& info : station.sessions()) station.keep_for_server(info.id, remote.name());
  const SyncReport second = sync_outbox(station, station_file, remote);
  EXPECT_EQ(second.sent.size(), 2u);

  const std::vector<SessionInfo> on_server = remote.sessions();
  ASSERT_EQ(on_server.size(), 2u);
  for (const NewSession& n : {half, unseen}) {
    const std::optional<SessionInfo> info = remote.find_uid(n.uid);
    ASSERT_TRUE(info);
    EXPECT_TRUE(info->complete);
    EXPECT_EQ(info->station, "station-07");
    EXPECT_EQ(info->started_at, n.started_at);
    EXPECT_EQ(info->ended_at, "2026-11-20T12:00:00Z");
    EXPECT_DOUBLE_EQ(info->score, a_result().score.total);
    const StoredSession s = remote.load(info->id);
    ASSERT_EQ(s.steps.size(), 2u);
    expect_same_metrics(s.overall, a_result().overall);
    EXPECT_EQ(s.components.size(), 2u);
    EXPECT_EQ(remote.recording(info->id), bytes);  // every byte once, in order
  }
}

}  // namespace
}  // namespace needle::training
