// The session store (docs/SESSIONS.md): trainees, tasks, sessions, per-step results, metrics,
// score breakdowns, each session's station and recording, in an SQLite file or on a PostgreSQL
// server (`location`: a file, or postgresql://...). Same schema and migrations on both, applied
// on open. A session is inserted `incomplete` when it starts and made `complete`, with everything
// it scored, in one transaction when it ends: a run that dies leaves an incomplete session and a
// readable database. One SessionStore per thread (each is one connection).
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "training/scoring/session_scorer.hpp"
#include "training/sessions/session_check.hpp"
#include "training/sessions/session_schema.hpp"
#include "training/sessions/sql_connection.hpp"

namespace needle::training {

struct SessionInfo {
  int64_t id = 0;
  std::string trainee;
  std::string task;         // Task::name
  std::string task_title;   // Task::title
  std::string task_source;  // the task file (Task::source): review loads its markers and scene
  std::string device;       // "" when not recorded (sessions from schema 1)
  std::string started_at;   // ISO 8601 UTC, "2026-11-21T12:00:00Z"
  std::string ended_at;     // "" while incomplete
  bool complete = false;
  double score = 0.0;  // valid when complete
  bool passed = false;
  double duration_s = 0.0;
  std::string recording_path;  // "" when none
  std::string station;         // "" for sessions from schema 1-2
  std::string uid;             // the id its station made (sync), "" for sessions from schema 1-2
  // Its latest check against its recording (needle-sim verify): none yet, or the outcome and the
  // score it found stored (training/sessions/session_check.hpp, verification()).
  std::optional<CheckOutcome> check;
  double checked_score = NAN;
};

struct StoredSession {
  SessionInfo info;
  std::vector<StepResult> steps;
  Metrics overall;
  std::vector<ScoreComponent> components;  // empty for sessions from schema 1
  std::optional<SessionCheck> check;       // the latest check against its recording, if any
};

// A trainee's name corrected (SessionStore::rename_trainee), as the store logged it.
struct TraineeRename {
  std::string old_name, new_name;
  std::string renamed_at;  // ISO 8601 UTC
  std::string renamed_by;  // the login role on PostgreSQL; "" on SQLite (a file has no users)
};

// What a new session is. `uid` empty: one is made; `started_at` empty: now.
struct NewSession {
  std::string trainee;
  std::string task, task_title, task_source;
  std::string device;
  std::string recording_path;
  std::string station;
  std::string uid;
  std::string started_at;
};

// Opens an existing store for reading only (review, report): nothing is created, migrated or
// written, so a database in a read-only folder or on a read-only disk can be reviewed.
struct ReadOnly {};
inline constexpr ReadOnly kReadOnly{};

class SessionStore {
 public:
  // Opens or creates the database at `location` and migrates it to `schema_version` (tests pass
  // an older one to make an old database). An SQLite file is checked first (PRAGMA quick_check)
  // and a damaged one refused, untouched. Throws SessionStoreError naming the database.
  explicit SessionStore(const std::string& location, int schema_version = kSessionSchemaVersion);
  SessionStore(const std::string& location, ReadOnly);
  ~SessionStore();
  SessionStore(const SessionStore&) = delete;
  SessionStore& operator=(const SessionStore&) = delete;

  SqlEngine engine() const { return db_->engine(); }
  const std::string& name() const { return db_->name(); }  // never with a password
  int schema_version() const;

  // Inserts an incomplete session (and its trainee and task when new: an existing one is left as
  // it is) and commits it at once. On PostgreSQL a station's role may begin sessions only in its own
  // name: a refusal says when `station` is not the login role.
  int64_t begin_session(const NewSession& session);
  int64_t begin_session(const std::string& trainee, const Task& task, const std::string& device,
                        const std::string& recording_path, const std::string& station = "");
  // Writes the steps, metrics and score and then marks the session complete, in one transaction;
  // from then on nothing of it can change (the schema's triggers refuse it). `ended_at` empty: now.
  void finish_session(int64_t id, const SessionResult& result, const std::string& ended_at = "");

  std::vector<SessionInfo> sessions() const;  // newest first
  // Throws if there is no such session, or when what is stored cannot be a session's (a complete
  // session's score outside 0-100 or not a number, a duration below 0): damaged or altered.
  StoredSession load(int64_t id) const;
  std::optional<SessionInfo> find_uid(const std::string& uid) const;

  // The recording kept in the database (PostgreSQL): appended chunk by chunk as it is written,
  // each with its CRC-32. `offset` must be where the stored bytes end (recording_bytes()).
  void append_recording(int64_t id, int64_t offset, const std::string& bytes);
  int64_t recording_bytes(int64_t id) const;
  // The stored bytes, every chunk checked (its CRC, and that it starts where the one before ended);
  // nullopt when the session has none. Throws SessionStoreError naming the session and the offset.
  std::optional<std::string> recording(int64_t id) const;

  // An instructor's correction of a trainee's name, logged by the store itself (trainee_renames,
  // whatever program renames): throws when there is no trainee `from`, or `to` is empty, longer than
  // kMaxNameBytes or another trainee's name.
  TraineeRename rename_trainee(const std::string& from, const std::string& to);
  std::vector<TraineeRename> trainee_renames() const;  // oldest first

  // Keeps a check of a session against its recording (needle-sim verify); `checked_at` empty: now,
  // `checked_by` on PostgreSQL: the login role whatever is given.
  void record_check(const SessionCheck& check);

  // The outbox: sessions this station kept for the server `server` (shown form) it could not reach.
  void keep_for_server(int64_t id, const std::string& server);
  std::vector<int64_t> outbox() const;
  void sent(int64_t id);

 private:
  std::unique_ptr<SqlConnection> db_;
};

// The result a stored session holds (steps, metrics, score and its breakdown; no reasons), to
// store it again elsewhere (sync).
SessionResult stored_result(const StoredSession& stored);

// Now, as the store writes times: ISO 8601 UTC to the second, "2026-11-21T12:00:00Z".
std::string utc_timestamp();

// A session id no other station makes: 128 random bits from the system's generator, in hex.
std::string new_session_uid();

}  // namespace needle::training
