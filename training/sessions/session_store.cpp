#include "training/sessions/session_store.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <random>
#include <type_traits>

#include "haptics/recording/crc32.hpp"
#include "training/scoring/metric_fields.hpp"
#include "training/sessions/postgres_connection.hpp"
#include "training/sessions/sqlite_connection.hpp"
#include "training/sessions/store_location.hpp"
#include "training/tasks/task.hpp"

namespace needle::training {

std::string utc_timestamp() {
  const std::time_t t = std::chrono::system_clock::to_time_t(std::chrono::system_clock::now());
  std::tm tm{};
  gmtime_r(&t, &tm);
  char text[32];
  std::strftime(text, sizeof text, "%Y-%m-%dT%H:%M:%SZ", &tm);
  return text;
}

namespace {

std::unique_ptr<SqlConnection> connect(const std::string& location, bool read_only) {
  if (is_postgres_uri(location)) return std::make_unique<PostgresConnection>(location, read_only);
  return std::make_unique<SqliteConnection>(location, read_only);
}

// The columns session_info() reads; a database before schema 3 has no station and no uid, one
// before schema 4 no checks.
std::string session_select(int version) {
  const char* latest_check = "(SELECT %s FROM session_checks c WHERE c.session_id = s.id ORDER BY c.id DESC LIMIT 1)";
  char outcome[160], score[160];
  std::snprintf(outcome, sizeof outcome, latest_check, "c.outcome");
  std::snprintf(score, sizeof score, latest_check, "c.score");
  return std::string(
             "SELECT s.id, r.name, t.name, coalesce(s.device, ''), s.started_at, coalesce(s.ended_at, ''), s.status, "
             "coalesce(s.score, 0), coalesce(s.passed, 0), coalesce(s.duration_s, 0), "
             "coalesce(s.recording_path, ''), t.title, t.source, ") +
         (version >= 3 ? "coalesce(s.station, ''), coalesce(s.uid, '')" : "'', ''") + ", " +
         (version >= 4 ? std::string(outcome) + ", " + score : "NULL, NULL") +
         " FROM sessions s JOIN trainees r ON r.id = s.trainee_id JOIN tasks t ON t.id = s.task_id ";
}

SessionInfo session_info(const SqlRow& s) {
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
  i.station = s.text(13);
  i.uid = s.text(14);
  if (CheckOutcome outcome; check_outcome_from_name(s.text(15), outcome)) i.check = outcome;
  i.checked_score = s.real(16);
  return i;
}

// Metrics as a stored session has them before its rows are read: a number the store does not hold
// (a metric added after the session was stored, or any of an incomplete session's) is not
// applicable, never a zero; counts stay 0.
Metrics unrecorded_metrics() {
  Metrics m;
  for_each_metric(m, [](const char*, auto& field) {
    if constexpr (std::is_floating_point_v<std::remove_reference_t<decltype(field)>>) field = kNotApplicable;
  });
  return m;
}

// A complete session's score and duration as no run stores them (a score outside 0-100, not a
// number, a negative duration) are damage or an alteration, refused naming the session.
void check_stored_numbers(const std::string& db, const SessionInfo& i) {
  const auto refuse = [&](const std::string& what, double v) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", v);
    throw StoredValueError(db + ": session " + std::to_string(i.id) + ": the stored " + what + " " + text +
                           " is outside what a run stores (" + (what == "score" ? "0 to 100" : "0 or more") +
                           "): the store is damaged or was altered; needle-sim verify --session " +
                           std::to_string(i.id) + " checks it against its recording");
  };
  if (!i.complete) return;
  if (!(i.score >= 0.0 && i.score <= 100.0)) refuse("score", i.score);
  if (!(i.duration_s >= 0.0 && std::isfinite(i.duration_s))) refuse("duration", i.duration_s);
}

// What a station's role was refused when it began a session in another name: the server says only
// that a row broke a policy.
std::string station_role_hint(SqlConnection& db, const std::string& station) {
  if (db.engine() != SqlEngine::kPostgres) return "";
  try {
    const std::string role = db.query("SELECT session_user", {}, "reading the login role").rows.at(0).text(0);
    if (role == station) return "";
    return " (the station name \"" + station + "\" must be this station's login role, \"" + role +
           "\": --station NAME, default the host name, names the role the server knows the station by)";
  } catch (const SessionStoreError&) {
    return "";
  }
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

double SqlRow::real(size_t c) const {
  const SqlValue& v = values.at(c);
  if (const auto* d = std::get_if<double>(&v)) return *d;
  if (const auto* i = std::get_if<int64_t>(&v)) return double(*i);
  return kNotApplicable;
}

int64_t SqlRow::integer(size_t c) const {
  const SqlValue& v = values.at(c);
  if (const auto* i = std::get_if<int64_t>(&v)) return *i;
  if (const auto* d = std::get_if<double>(&v)) return int64_t(*d);
  return 0;
}

std::string SqlRow::text(size_t c) const {
  const SqlValue& v = values.at(c);
  if (const auto* s = std::get_if<std::string>(&v)) return *s;
  if (const auto* i = std::get_if<int64_t>(&v)) return std::to_string(*i);
  return "";
}

const std::string& SqlRow::blob(size_t c) const {
  static const std::string none;
  const auto* b = std::get_if<SqlBlob>(&values.at(c));
  return b ? b->bytes : none;
}

SessionStore::SessionStore(const std::string& location, ReadOnly) : db_(connect(location, true)) {
  check_schema_readable(*db_);
}

SessionStore::SessionStore(const std::string& location, int schema_version) {
  if (schema_version < 1 || schema_version > kSessionSchemaVersion)
    throw SessionStoreError(shown_location(location) + ": cannot make schema version " +
                            std::to_string(schema_version));
  db_ = connect(location, false);
  migrate_schema(*db_, schema_version);
}

SessionStore::~SessionStore() = default;

int SessionStore::schema_version() const { return training::schema_version(*db_); }

int64_t SessionStore::begin_session(const std::string& trainee, const Task& task, const std::string& device,
                                    const std::string& recording_path, const std::string& station) {
  return begin_session({trainee, task.name, task.title, task.source, device, recording_path, station, "", ""});
}

int64_t SessionStore::begin_session(const NewSession& n) {
  const std::string what = "starting a session";
  try {
    SqlTransaction transaction(*db_, what);
    // A trainee or task already stored is left as it is: stations insert them, never change them.
    const auto id_of = [&](const std::string& insert, const std::string& table, const std::vector<SqlValue>& values) {
      db_->query(insert + " ON CONFLICT(name) DO NOTHING", values, what);
      return db_->query("SELECT id FROM " + table + " WHERE name = ?", {values.at(0)}, what).rows.at(0).integer(0);
    };
    const int64_t trainee_id = id_of("INSERT INTO trainees(name) VALUES (?)", "trainees", {n.trainee});
    const int64_t task_id = id_of("INSERT INTO tasks(name, title, source) VALUES (?, ?, ?)", "tasks",
                                  {n.task, n.task_title, n.task_source});
    std::vector<SqlValue> values{trainee_id, task_id, n.started_at.empty() ? utc_timestamp() : n.started_at,
                                 n.recording_path, n.device};
    std::string sql = "INSERT INTO sessions(trainee_id, task_id, started_at, status, recording_path, device";
    if (schema_version() >= 3) {  // tests make older databases through this program
      sql += ", station, uid) VALUES (?, ?, ?, 'incomplete', ?, ?, ?, ?) RETURNING id";
      values.emplace_back(n.station);
      values.emplace_back(n.uid.empty() ? new_session_uid() : n.uid);
    } else {
      sql += ") VALUES (?, ?, ?, 'incomplete', ?, ?) RETURNING id";
    }
    const int64_t id = db_->query(sql, values, what).rows.at(0).integer(0);
    transaction.commit();
    return id;
  } catch (const SessionStoreError& e) {
    const std::string hint = station_role_hint(*db_, n.station);
    if (hint.empty()) throw;
    throw SessionStoreError(e.what() + hint);
  }
}

void SessionStore::finish_session(int64_t id, const SessionResult& result, const std::string& ended_at) {
  const std::string what = "finishing session " + std::to_string(id);
  SqlTransaction transaction(*db_, what);
  // Its rows first, then complete: once complete, the session takes no more rows.
  const SqlResult open = db_->query("SELECT 1 FROM sessions WHERE id = ? AND status = 'incomplete'", {id}, what);
  if (open.rows.empty()) throw SessionStoreError(db_->name() + ": " + what + ": no incomplete session with that id");
  const auto write_metrics = [&](int64_t index, const Metrics& m) {
    for_each_metric(m, [&](const char* name, auto value) {
      db_->query("INSERT INTO metrics VALUES (?, ?, ?, ?)", {id, index, std::string(name), static_cast<double>(value)},
                 what);
    });
  };
  for (size_t i = 0; i < result.steps.size(); ++i) {
    const StepResult& s = result.steps[i];
    db_->query(
        "INSERT INTO step_results VALUES (?, ?, ?, ?, ?, ?)",
        {id, int64_t(i), s.id, std::string(step_outcome_name(s.record.outcome)), s.record.start_s, s.record.end_s},
        what);
    write_metrics(int64_t(i), s.metrics);
  }
  write_metrics(-1, result.overall);
  for (size_t i = 0; i < result.score.components.size(); ++i) {
    const ScoreComponent& c = result.score.components[i];
    db_->query("INSERT INTO score_components VALUES (?, ?, ?, ?, ?)", {id, int64_t(i), c.name, c.value, c.weight},
               what);
  }
  const SqlResult done = db_->query(
      "UPDATE sessions SET status = 'complete', ended_at = ?, score = ?, passed = ?, duration_s = ? "
      "WHERE id = ? AND status = 'incomplete'",
      {ended_at.empty() ? utc_timestamp() : ended_at, result.score.total, int64_t{result.score.passed},
       result.overall.duration_s, id},
      what);
  if (done.changes != 1) throw SessionStoreError(db_->name() + ": " + what + ": no incomplete session with that id");
  transaction.commit();
}

std::vector<SessionInfo> SessionStore::sessions() const {
  std::vector<SessionInfo> out;
  for (const SqlRow& row :
       db_->query(session_select(schema_version()) + "ORDER BY s.id DESC", {}, "listing sessions").rows)
    out.push_back(session_info(row));
  return out;
}

StoredSession SessionStore::load(int64_t id) const {
  const std::string what = "reading session " + std::to_string(id);
  // One read transaction: a writer finishing this session meanwhile is seen wholly or not at all.
  SqlTransaction snapshot(*db_, what, false);
  StoredSession out;
  out.overall = unrecorded_metrics();
  const int version = schema_version();
  const SqlResult s = db_->query(session_select(version) + "WHERE s.id = ?", {id}, what);
  if (s.rows.empty()) throw SessionStoreError(db_->name() + ": " + what + ": no such session");
  out.info = session_info(s.rows[0]);
  for (const SqlRow& row : db_->query("SELECT step_id, outcome, start_s, end_s FROM step_results WHERE session_id = ? "
                                      "ORDER BY step_index",
                                      {id}, what)
                               .rows) {
    StepResult r;
    r.metrics = unrecorded_metrics();
    r.id = row.text(0);
    if (!step_outcome_from_name(row.text(1), r.record.outcome))
      throw SessionStoreError(db_->name() + ": " + what + ": unknown step outcome \"" + row.text(1) + "\"");
    r.record.start_s = row.real(2);
    r.record.end_s = row.real(3);
    out.steps.push_back(r);
  }
  for (const SqlRow& row :
       db_->query("SELECT step_index, name, value FROM metrics WHERE session_id = ?", {id}, what).rows) {
    const int64_t index = row.integer(0);
    if (index < -1 || index >= int64_t(out.steps.size()))
      throw SessionStoreError(db_->name() + ": " + what + ": a metric of step " + std::to_string(index) +
                              ", which it has not");
    // Names this program does not know (from a newer one) are skipped.
    set_metric(index < 0 ? out.overall : out.steps[size_t(index)].metrics, row.text(1), row.real(2));
  }
  if (version >= 2) {
    for (const SqlRow& row :
         db_->query("SELECT name, value, weight FROM score_components WHERE session_id = ? ORDER BY position", {id},
                    what)
             .rows)
      out.components.push_back({row.text(0), row.real(1), row.real(2)});
    // The store keeps a component's value and weight; whether it applied follows from them and the
    // session's metrics as the score decided it (a score from before the statuses: any points, applied).
    const bool every_step_completed = !out.steps.empty() && completed_steps(out.steps) == long(out.steps.size());
    for (ScoreComponent& c : out.components)
      c.status = c.weight == 0.0 ? ComponentStatus::kNotApplicable
                 : c.value > 0.0 || component_reached(c.name, out.overall, every_step_completed)
                     ? ComponentStatus::kApplied
                     : ComponentStatus::kNotReached;
  }
  if (version >= 4) {
    const SqlResult c = db_->query(
        "SELECT outcome, score, digest, detail, checked_at, checked_by FROM session_checks "
        "WHERE session_id = ? ORDER BY id DESC LIMIT 1",
        {id}, what);
    if (!c.rows.empty()) {
      SessionCheck check{id,
                         CheckOutcome::kUnverifiable,
                         c.rows[0].real(1),
                         c.rows[0].text(2),
                         c.rows[0].text(3),
                         c.rows[0].text(4),
                         c.rows[0].text(5)};
      check_outcome_from_name(c.rows[0].text(0), check.outcome);
      out.check = check;
    }
  }
  snapshot.commit();
  check_stored_numbers(db_->name(), out.info);
  return out;
}

TraineeRename SessionStore::rename_trainee(const std::string& from, const std::string& to) {
  const std::string what = "renaming trainee \"" + from + "\" to \"" + to + "\"";
  if (to.empty() || to.size() > kMaxNameBytes)
    throw SessionStoreError(db_->name() + ": " + what + ": a name has 1 to " + std::to_string(kMaxNameBytes) +
                            " bytes");
  SqlTransaction transaction(*db_, what);
  if (!db_->query("SELECT 1 FROM trainees WHERE name = ?", {to}, what).rows.empty())
    throw SessionStoreError(db_->name() + ": " + what + ": a trainee named \"" + to + "\" exists already");
  if (db_->query("UPDATE trainees SET name = ? WHERE name = ?", {to, from}, what).changes != 1)
    throw SessionStoreError(db_->name() + ": " + what + ": no trainee named \"" + from + "\"");
  const SqlResult logged = db_->query(
      "SELECT old_name, new_name, renamed_at, renamed_by FROM trainee_renames ORDER BY id DESC LIMIT 1", {}, what);
  transaction.commit();
  const SqlRow& row = logged.rows.at(0);
  return {row.text(0), row.text(1), row.text(2), row.text(3)};
}

std::vector<TraineeRename> SessionStore::trainee_renames() const {
  std::vector<TraineeRename> out;
  for (const SqlRow& row :
       db_->query("SELECT old_name, new_name, renamed_at, renamed_by FROM trainee_renames ORDER BY id", {},
                  "reading the trainees' renames")
           .rows)
    out.push_back({row.text(0), row.text(1), row.text(2), row.text(3)});
  return out;
}

void SessionStore::record_check(const SessionCheck& c) {
  const std::string at = c.checked_at.empty() ? utc_timestamp() : c.checked_at;
  const std::string what = "keeping the check of session " + std::to_string(c.session_id);
  const std::string by = engine() == SqlEngine::kPostgres ? "session_user" : "?";
  std::vector<SqlValue> values{c.session_id, at,       std::string(check_outcome_name(c.outcome)),
                               c.score,      c.digest, c.detail};
  if (engine() == SqlEngine::kSqlite) values.emplace_back(c.checked_by);
  db_->query(
      "INSERT INTO session_checks(session_id, checked_at, outcome, score, digest, detail, checked_by) "
      "VALUES (?, ?, ?, ?, ?, ?, " +
          by + ")",
      values, what);
}

std::optional<SessionInfo> SessionStore::find_uid(const std::string& uid) const {
  const SqlResult r = db_->query(session_select(schema_version()) + "WHERE s.uid = ?", {uid}, "finding session " + uid);
  if (r.rows.empty()) return std::nullopt;
  return session_info(r.rows[0]);
}

void SessionStore::append_recording(int64_t id, int64_t offset, const std::string& bytes) {
  const std::string what =
      "storing the recording of session " + std::to_string(id) + " from byte " + std::to_string(offset);
  const int64_t crc = haptics::crc32(bytes.data(), bytes.size());
  db_->query("INSERT INTO recording_chunks VALUES (?, ?, ?, ?)", {id, offset, SqlBlob{bytes}, crc}, what);
}

int64_t SessionStore::recording_bytes(int64_t id) const {
  return db_
      ->query("SELECT coalesce(max(byte_offset + length(bytes)), 0) FROM recording_chunks WHERE session_id = ?", {id},
              "measuring the recording of session " + std::to_string(id))
      .rows.at(0)
      .integer(0);
}

std::optional<std::string> SessionStore::recording(int64_t id) const {
  const std::string what = "reading the recording of session " + std::to_string(id);
  std::string out;
  bool any = false;
  // A batch of chunks a query, so no query holds a long recording twice over.
  for (;;) {
    const SqlResult r = db_->query(
        "SELECT byte_offset, bytes, crc FROM recording_chunks WHERE session_id = ? AND byte_offset >= ? "
        "ORDER BY byte_offset LIMIT 256",
        {id, int64_t(out.size())}, what);
    if (r.rows.empty()) break;
    any = true;
    for (const SqlRow& row : r.rows) {
      const int64_t offset = row.integer(0);
      const std::string& bytes = row.blob(1);
      if (offset != int64_t(out.size()))
        throw SessionStoreError(db_->name() + ": " + what + ": chunk at byte " + std::to_string(offset) +
                                ", expected " + std::to_string(out.size()) + " (a chunk is missing or overlaps)");
      if (int64_t(haptics::crc32(bytes.data(), bytes.size())) != row.integer(2))
        throw SessionStoreError(db_->name() + ": " + what + ": chunk at byte " + std::to_string(offset) +
                                ": checksum mismatch (damaged)");
      out += bytes;
    }
  }
  if (!any) return std::nullopt;
  return out;
}

void SessionStore::keep_for_server(int64_t id, const std::string& server) {
  db_->query("INSERT INTO outbox VALUES (?, ?) ON CONFLICT(session_id) DO UPDATE SET server = excluded.server",
             {id, server}, "keeping session " + std::to_string(id) + " to send");
}

std::vector<int64_t> SessionStore::outbox() const {
  std::vector<int64_t> ids;
  for (const SqlRow& row :
       db_->query("SELECT session_id FROM outbox ORDER BY session_id", {}, "reading the outbox").rows)
    ids.push_back(row.integer(0));
  return ids;
}

void SessionStore::sent(int64_t id) {
  db_->query("DELETE FROM outbox WHERE session_id = ?", {id}, "marking session " + std::to_string(id) + " sent");
}

SessionResult stored_result(const StoredSession& stored) {
  SessionResult r;
  r.steps = stored.steps;
  r.overall = stored.overall;
  r.score.total = stored.info.score;
  r.score.passed = stored.info.passed;
  r.score.components = stored.components;
  r.finished = stored.info.complete;
  return r;
}

std::string new_session_uid() {
  std::random_device random;  // /dev/urandom
  char text[33];
  std::snprintf(text, sizeof text, "%08x%08x%08x%08x", random(), random(), random(), random());
  return text;
}

}  // namespace needle::training
