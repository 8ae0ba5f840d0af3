#include "training/sessions/session_store.hpp"

#include <sqlite3.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>

#include "training/scoring/metric_fields.hpp"

namespace needle::training {

namespace {

// Migration i takes the schema from version i to i + 1 (PRAGMA user_version). Never edit one
// that has shipped: add the next.
const char* const kMigrations[] = {
    // 1: trainees, tasks, sessions, per-step results, metrics (step_index -1: the whole session).
    R"sql(
    CREATE TABLE trainees (id INTEGER PRIMARY KEY, name TEXT NOT NULL UNIQUE);
    CREATE TABLE tasks (id INTEGER PRIMARY KEY, name TEXT NOT NULL UNIQUE, title TEXT NOT NULL, source TEXT NOT NULL);
    CREATE TABLE sessions (
      id INTEGER PRIMARY KEY,
      trainee_id INTEGER NOT NULL REFERENCES trainees(id),
      task_id INTEGER NOT NULL REFERENCES tasks(id),
      started_at TEXT NOT NULL,
      ended_at TEXT,
      status TEXT NOT NULL CHECK (status IN ('incomplete', 'complete')),
      score REAL,
      passed INTEGER,
      duration_s REAL,
      recording_path TEXT);
    CREATE INDEX sessions_by_trainee ON sessions(trainee_id);
    CREATE INDEX sessions_by_task ON sessions(task_id);
    CREATE TABLE step_results (
      session_id INTEGER NOT NULL REFERENCES sessions(id) ON DELETE CASCADE,
      step_index INTEGER NOT NULL,
      step_id TEXT NOT NULL,
      outcome TEXT NOT NULL,
      start_s REAL,
      end_s REAL,
      PRIMARY KEY (session_id, step_index));
    CREATE TABLE metrics (
      session_id INTEGER NOT NULL REFERENCES sessions(id) ON DELETE CASCADE,
      step_index INTEGER NOT NULL,
      name TEXT NOT NULL,
      value REAL,
      PRIMARY KEY (session_id, step_index, name));
    )sql",
    // 2: the device a session ran on, and the score's breakdown for the trainee and review panels.
    R"sql(
    ALTER TABLE sessions ADD COLUMN device TEXT;
    CREATE TABLE score_components (
      session_id INTEGER NOT NULL REFERENCES sessions(id) ON DELETE CASCADE,
      position INTEGER NOT NULL,
      name TEXT NOT NULL,
      value REAL NOT NULL,
      weight REAL NOT NULL,
      PRIMARY KEY (session_id, position));
    )sql",
};
static_assert(std::size(kMigrations) == kSessionSchemaVersion);

std::string now_utc() {
  const std::time_t t = std::chrono::system_clock::to_time_t(std::chrono::system_clock::now());
  std::tm tm{};
  gmtime_r(&t, &tm);
  char text[32];
  std::strftime(text, sizeof text, "%Y-%m-%dT%H:%M:%SZ", &tm);
  return text;
}

// One prepared statement; binds count from 1, columns from 0. NaN is stored as NULL and read
// back as NaN (a metric that does not apply). Errors read "WHERE: what failed: SQLite's message",
// `where` naming the file and the operation.
class Statement {
 public:
  Statement(sqlite3* db, std::string where, const std::string& sql) : db_(db), where_(std::move(where)) {
    if (sqlite3_prepare_v2(db, sql.c_str(), -1, &stmt_, nullptr) != SQLITE_OK) fail("preparing a statement");
  }
  ~Statement() { sqlite3_finalize(stmt_); }
  Statement(const Statement&) = delete;
  Statement& operator=(const Statement&) = delete;

  Statement& bind(int i, double v) {
    check(std::isnan(v) ? sqlite3_bind_null(stmt_, i) : sqlite3_bind_double(stmt_, i, v));
    return *this;
  }
  Statement& bind(int i, int64_t v) {
    check(sqlite3_bind_int64(stmt_, i, v));
    return *this;
  }
  Statement& bind(int i, const std::string& v) {
    check(sqlite3_bind_text(stmt_, i, v.c_str(), -1, SQLITE_TRANSIENT));
    return *this;
  }
  // True while there is a row.
  bool step() {
    const int rc = sqlite3_step(stmt_);
    if (rc == SQLITE_ROW) return true;
    if (rc != SQLITE_DONE) fail("running a statement");
    return false;
  }
  // Runs a statement that returns no row, ready to be bound again.
  void run() {
    step();
    sqlite3_reset(stmt_);
  }
  // The integer of the single row a statement returns (INSERT ... RETURNING id), then done.
  int64_t single_integer() {
    if (!step()) fail("expected a row");
    const int64_t value = integer(0);
    sqlite3_reset(stmt_);  // a statement left mid-way would block the COMMIT
    return value;
  }
  void reset() { sqlite3_reset(stmt_); }
  double real(int c) const {
    return sqlite3_column_type(stmt_, c) == SQLITE_NULL ? kNotApplicable : sqlite3_column_double(stmt_, c);
  }
  int64_t integer(int c) const { return sqlite3_column_int64(stmt_, c); }
  std::string text(int c) const {
    const unsigned char* t = sqlite3_column_text(stmt_, c);
    return t ? reinterpret_cast<const char*>(t) : "";
  }

 private:
  [[noreturn]] void fail(const char* what) const {
    throw SessionStoreError(where_ + ": " + what + ": " + sqlite3_errmsg(db_));
  }
  void check(int rc) {
    if (rc != SQLITE_OK) fail("binding a value");
  }
  sqlite3* db_;
  std::string where_;
  sqlite3_stmt* stmt_ = nullptr;
};

// BEGIN on construction, ROLLBACK on destruction unless commit() ran: an exception anywhere in
// between leaves the file as it was.
class Transaction {
 public:
  Transaction(sqlite3* db, std::string where, const char* begin = "BEGIN IMMEDIATE")
      : db_(db), where_(std::move(where)) {
    run(begin);
  }
  ~Transaction() {
    if (open_) sqlite3_exec(db_, "ROLLBACK", nullptr, nullptr, nullptr);
  }
  Transaction(const Transaction&) = delete;
  Transaction& operator=(const Transaction&) = delete;
  void commit() {
    run("COMMIT");
    open_ = false;
  }

 private:
  void run(const char* sql) {
    if (sqlite3_exec(db_, sql, nullptr, nullptr, nullptr) != SQLITE_OK)
      throw SessionStoreError(where_ + ": " + sql + ": " + sqlite3_errmsg(db_));
  }
  sqlite3* db_;
  std::string where_;
  bool open_ = true;
};

// `file` as an SQLite URI with `query`, the characters a URI gives a meaning to escaped.
std::string file_uri(const std::string& file, const char* query) {
  std::string uri = "file:";
  for (const char c : std::filesystem::absolute(file).string()) {
    if (c == '?' || c == '#' || c == '%') {
      char escaped[4];
      std::snprintf(escaped, sizeof escaped, "%%%02X", static_cast<unsigned char>(c));
      uri += escaped;
    } else {
      uri += c;
    }
  }
  return uri + "?" + query;
}

}  // namespace

void SessionStore::exec(const char* sql, const std::string& what) const {
  char* message = nullptr;
  if (sqlite3_exec(db_, sql, nullptr, nullptr, &message) != SQLITE_OK) {
    const std::string text = message ? message : "unknown error";
    sqlite3_free(message);
    throw SessionStoreError(file_ + ": " + (what.empty() ? "running \"" + std::string(sql) + "\"" : what) + ": " +
                            text);
  }
}

void SessionStore::open(int flags, const std::string& name) {
  if (sqlite3_open_v2(name.c_str(), &db_, flags, nullptr) != SQLITE_OK) {
    const std::string message = db_ ? sqlite3_errmsg(db_) : "out of memory";
    sqlite3_close(db_);
    db_ = nullptr;
    throw SessionStoreError(file_ + ": opening the session database: " + message);
  }
  sqlite3_busy_timeout(db_, 10000);  // a writer holds the lock for one short transaction
}

// A damaged file (a zeroed page, a cut) is refused before anything reads or writes it: a run must
// not simulate a whole task and then lose it, a report must not show a session with parts missing.
void SessionStore::check_integrity() const {
  std::string problem;  // quick_check's first line that is not "ok", or why SQLite could not run it
  auto first_problem = [](void* out, int, char** values, char**) {
    auto& text = *static_cast<std::string*>(out);
    if (text.empty() && values[0] != nullptr && std::string(values[0]) != "ok") text = values[0];
    return 0;
  };
  char* message = nullptr;
  if (sqlite3_exec(db_, "PRAGMA quick_check", first_problem, &problem, &message) != SQLITE_OK) {
    problem = message ? message : sqlite3_errmsg(db_);  // the file itself refused: "file is not a database", ...
    sqlite3_free(message);
  }
  if (!problem.empty())
    throw SessionStoreError(file_ + ": the session database is damaged (PRAGMA quick_check: " + problem +
                            "); it was left as it is: restore a copy, or move it away to start a new one");
}

SessionStore::SessionStore(const std::filesystem::path& file, ReadOnly) : file_(file.string()) {
  open(SQLITE_OPEN_READONLY, file_);
  try {
    // A reader of a WAL database needs its -shm file. In a folder it cannot write, where none
    // exists (so no run is writing the file: a writer makes one), SQLite cannot open it for
    // reading; it then reads it as immutable, which needs no -shm.
    const bool no_shm = !std::filesystem::exists(file_ + "-shm");
    if (no_shm && sqlite3_exec(db_, "SELECT 1 FROM sqlite_master LIMIT 1", nullptr, nullptr, nullptr) == SQLITE_CANTOPEN) {
      sqlite3_close(db_);
      db_ = nullptr;
      open(SQLITE_OPEN_READONLY | SQLITE_OPEN_URI, file_uri(file_, "immutable=1"));
    }
    check_integrity();
    const int found = schema_version();
    if (found < 1) throw SessionStoreError(file_ + ": not a session database (it has no schema version)");
    if (found > kSessionSchemaVersion)
      throw SessionStoreError(file_ + ": schema version " + std::to_string(found) + " is newer than this program's " +
                              std::to_string(kSessionSchemaVersion));
  } catch (...) {
    sqlite3_close(db_);
    throw;
  }
}

SessionStore::SessionStore(const std::filesystem::path& file, int schema_version) : file_(file.string()) {
  if (schema_version < 1 || schema_version > kSessionSchemaVersion)
    throw SessionStoreError(file_ + ": cannot make schema version " + std::to_string(schema_version));
  open(SQLITE_OPEN_READWRITE | SQLITE_OPEN_CREATE, file_);
  try {
    check_integrity();
    exec("PRAGMA foreign_keys = ON");
    if (journal_mode() != "wal") {
      exec("PRAGMA journal_mode = WAL");
      if (journal_mode() != "wal") throw SessionStoreError(file_ + ": cannot switch the journal to WAL");
    }
    exec("PRAGMA synchronous = FULL");
    // Migrate under the write lock, re-reading the version: another process may have done it.
    Transaction migration(db_, file_ + ": migrating the schema");
    const int found = this->schema_version();
    if (found > kSessionSchemaVersion)
      throw SessionStoreError(file_ + ": schema version " + std::to_string(found) + " is newer than this program's " +
                              std::to_string(kSessionSchemaVersion));
    for (int v = found; v < schema_version; ++v) {
      exec(kMigrations[v], "migrating to schema version " + std::to_string(v + 1));
      exec(("PRAGMA user_version = " + std::to_string(v + 1)).c_str());
    }
    migration.commit();
  } catch (...) {
    sqlite3_close(db_);
    throw;
  }
}

SessionStore::~SessionStore() { sqlite3_close(db_); }

int SessionStore::schema_version() const {
  Statement s(db_, file_, "PRAGMA user_version");
  s.step();
  return static_cast<int>(s.integer(0));
}

std::string SessionStore::journal_mode() const {
  Statement s(db_, file_, "PRAGMA journal_mode");
  s.step();
  return s.text(0);
}

int64_t SessionStore::begin_session(const std::string& trainee, const Task& task, const std::string& device,
                                    const std::string& recording_path) {
  const std::string f = file_ + ": starting a session";
  Transaction transaction(db_, f);
  Statement t(
      db_, f,
      "INSERT INTO trainees(name) VALUES (?) ON CONFLICT(name) DO UPDATE SET name = excluded.name RETURNING id");
  const int64_t trainee_id = t.bind(1, trainee).single_integer();
  Statement k(db_, f,
              "INSERT INTO tasks(name, title, source) VALUES (?, ?, ?) ON CONFLICT(name) DO UPDATE SET "
              "title = excluded.title, source = excluded.source RETURNING id");
  const int64_t task_id = k.bind(1, task.name).bind(2, task.title).bind(3, task.source).single_integer();
  Statement s(db_, f,
              "INSERT INTO sessions(trainee_id, task_id, started_at, status, recording_path, device) "
              "VALUES (?, ?, ?, 'incomplete', ?, ?) RETURNING id");
  const int64_t id = s.bind(1, trainee_id)
                         .bind(2, task_id)
                         .bind(3, now_utc())
                         .bind(4, recording_path)
                         .bind(5, device)
                         .single_integer();
  transaction.commit();
  return id;
}

void SessionStore::finish_session(int64_t id, const SessionResult& result) {
  const std::string session = "finishing session " + std::to_string(id);
  const std::string f = file_ + ": " + session;
  Transaction transaction(db_, f);
  Statement done(db_, f,
                 "UPDATE sessions SET status = 'complete', ended_at = ?, score = ?, passed = ?, duration_s = ? "
                 "WHERE id = ? AND status = 'incomplete'");
  done.bind(1, now_utc()).bind(2, result.score.total).bind(3, int64_t{result.score.passed});
  done.bind(4, result.overall.duration_s).bind(5, id).run();
  if (sqlite3_changes(db_) != 1)
    throw SessionStoreError(file_ + ": " + session + ": no incomplete session with that id");
  Statement step(db_, f, "INSERT INTO step_results VALUES (?, ?, ?, ?, ?, ?)");
  Statement metric(db_, f, "INSERT INTO metrics VALUES (?, ?, ?, ?)");
  const auto write_metrics = [&](int64_t index, const Metrics& m) {
    for_each_metric(m, [&](const char* name, auto value) {
      metric.bind(1, id).bind(2, index).bind(3, std::string(name)).bind(4, static_cast<double>(value)).run();
    });
  };
  for (size_t i = 0; i < result.steps.size(); ++i) {
    const StepResult& s = result.steps[i];
    step.bind(1, id).bind(2, int64_t(i)).bind(3, s.id).bind(4, std::string(step_outcome_name(s.record.outcome)));
    step.bind(5, s.record.start_s).bind(6, s.record.end_s).run();
    write_metrics(int64_t(i), s.metrics);
  }
  write_metrics(-1, result.overall);
  Statement component(db_, f, "INSERT INTO score_components VALUES (?, ?, ?, ?, ?)");
  for (size_t i = 0; i < result.score.components.size(); ++i) {
    const ScoreComponent& c = result.score.components[i];
    component.bind(1, id).bind(2, int64_t(i)).bind(3, c.name).bind(4, c.value).bind(5, c.weight).run();
  }
  transaction.commit();
}

namespace {

constexpr const char* kSessionColumns =
    "SELECT s.id, r.name, t.name, coalesce(s.device, ''), s.started_at, coalesce(s.ended_at, ''), s.status, "
    "coalesce(s.score, 0), coalesce(s.passed, 0), coalesce(s.duration_s, 0), coalesce(s.recording_path, ''), "
    "t.title, t.source "
    "FROM sessions s JOIN trainees r ON r.id = s.trainee_id JOIN tasks t ON t.id = s.task_id ";

SessionInfo session_info(const Statement& s) {
  SessionInfo i;
  i.id = s.integer(0);
  i.trainee = s.text(1);
  i.task = s.text(2);
  i.device = s.text(3);
  i.started_at = s.text(4);
  i.ended_at = s.text(5);
  i.complete = s.text(6) == "complete";
  i.score = s.real(7);
  i.passed = s.integer(8) != 0;
  i.duration_s = s.real(9);
  i.recording_path = s.text(10);
  i.task_title = s.text(11);
  i.task_source = s.text(12);
  return i;
}

// Sets the field of `m` called `name`; false when no field has that name.
bool set_metric(Metrics& m, const std::string& name, double value) {
  bool found = false;
  for_each_metric(m, [&](const char* field_name, auto& field) {
    if (name != field_name) return;
    field = static_cast<std::remove_reference_t<decltype(field)>>(value);
    found = true;
  });
  return found;
}

}  // namespace

std::vector<SessionInfo> SessionStore::sessions() const {
  const std::string f = file_ + ": listing sessions";
  Statement s(db_, f, std::string(kSessionColumns) + "ORDER BY s.id DESC");
  std::vector<SessionInfo> out;
  while (s.step()) out.push_back(session_info(s));
  return out;
}

StoredSession SessionStore::load(int64_t id) const {
  const std::string session = "reading session " + std::to_string(id);
  const std::string f = file_ + ": " + session;
  // One read transaction: a writer finishing this session meanwhile is seen wholly or not at all.
  Transaction snapshot(db_, f, "BEGIN");
  StoredSession out;
  Statement s(db_, f, std::string(kSessionColumns) + "WHERE s.id = ?");
  s.bind(1, id);
  if (!s.step()) throw SessionStoreError(file_ + ": " + session + ": no such session");
  out.info = session_info(s);
  s.reset();
  Statement steps(db_, f,
                  "SELECT step_id, outcome, start_s, end_s FROM step_results WHERE session_id = ? ORDER BY step_index");
  steps.bind(1, id);
  while (steps.step()) {
    StepResult r;
    r.id = steps.text(0);
    if (!step_outcome_from_name(steps.text(1), r.record.outcome))
      throw SessionStoreError(file_ + ": " + session + ": unknown step outcome \"" + steps.text(1) + "\"");
    r.record.start_s = steps.real(2);
    r.record.end_s = steps.real(3);
    out.steps.push_back(r);
  }
  Statement metrics(db_, f, "SELECT step_index, name, value FROM metrics WHERE session_id = ?");
  metrics.bind(1, id);
  while (metrics.step()) {
    const int64_t index = metrics.integer(0);
    if (index < -1 || index >= int64_t(out.steps.size()))
      throw SessionStoreError(file_ + ": " + session + ": a metric of step " + std::to_string(index) +
                              ", which it has not");
    // Names this program does not know (from a newer one) are skipped.
    set_metric(index < 0 ? out.overall : out.steps[size_t(index)].metrics, metrics.text(1), metrics.real(2));
  }
  if (schema_version() >= 2) {
    Statement c(db_, f, "SELECT name, value, weight FROM score_components WHERE session_id = ? ORDER BY position");
    c.bind(1, id);
    while (c.step()) out.components.push_back({c.text(0), c.real(1), c.real(2)});
  }
  snapshot.commit();
  return out;
}

}  // namespace needle::training
