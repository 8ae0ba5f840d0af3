// The session store (docs/SESSIONS.md): an SQLite file of trainees, tasks, sessions, per-step
// results, metrics, score breakdowns and the path of each session's recording. Versioned schema
// migrated on open; WAL journal, so a review window can read while a trainee's run writes.
// A session is inserted `incomplete` when it starts and made `complete`, with everything it
// scored, in one transaction when it ends: a run that dies leaves an incomplete session and a
// readable file. One SessionStore per thread (each is one connection).
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "training/scoring/session_scorer.hpp"

struct sqlite3;

namespace needle::training {

// "FILE: what failed: SQLite's message".
struct SessionStoreError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

inline constexpr int kSessionSchemaVersion = 2;

struct SessionInfo {
  int64_t id = 0;
  std::string trainee;
  std::string task;        // Task::name
  std::string task_title;  // Task::title
  std::string task_source; // the task file (Task::source): review loads its markers and scene
  std::string device;      // "" when not recorded (sessions from schema 1)
  std::string started_at;  // ISO 8601 UTC, "2026-11-21T12:00:00Z"
  std::string ended_at;    // "" while incomplete
  bool complete = false;
  double score = 0.0;  // valid when complete
  bool passed = false;
  double duration_s = 0.0;
  std::string recording_path;  // "" when none
};

struct StoredSession {
  SessionInfo info;
  std::vector<StepResult> steps;
  Metrics overall;
  std::vector<ScoreComponent> components;  // empty for sessions from schema 1
};

// Opens an existing store for reading only (review, report): nothing is created, migrated or
// written, so a database in a read-only folder or on a read-only disk can be reviewed.
struct ReadOnly {};
inline constexpr ReadOnly kReadOnly{};

class SessionStore {
 public:
  // Opens or creates `file` and migrates it to `schema_version` (tests pass an older one to
  // make an old file). Both constructors check the file first (PRAGMA quick_check) and refuse a
  // damaged one, untouched. Throws SessionStoreError naming the file.
  explicit SessionStore(const std::filesystem::path& file, int schema_version = kSessionSchemaVersion);
  SessionStore(const std::filesystem::path& file, ReadOnly);
  ~SessionStore();
  SessionStore(const SessionStore&) = delete;
  SessionStore& operator=(const SessionStore&) = delete;

  int schema_version() const;
  std::string journal_mode() const;  // "wal"

  // Inserts an incomplete session (and its trainee and task when new) and commits it at once.
  int64_t begin_session(const std::string& trainee, const Task& task, const std::string& device,
                        const std::string& recording_path);
  // Writes the steps, metrics and score and marks the session complete, in one transaction.
  void finish_session(int64_t id, const SessionResult& result);

  std::vector<SessionInfo> sessions() const;  // newest first
  StoredSession load(int64_t id) const;       // throws if there is no such session

 private:
  void exec(const char* sql, const std::string& what = "") const;  // what failed, for the error
  void open(int flags, const std::string& name);  // name: the file, or an SQLite URI for it
  void check_integrity() const;

  std::string file_;
  sqlite3* db_ = nullptr;
};

}  // namespace needle::training
