#include "training/sessions/sqlite_connection.hpp"

#include <sqlite3.h>
#include <sys/statvfs.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <filesystem>

namespace needle::training {

namespace {

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

struct Finalize {
  void operator()(sqlite3_stmt* s) const { sqlite3_finalize(s); }
};

// What SQLite reads as the file damaged, a database it cannot read at all; anything else (a file it
// cannot open, a folder it cannot write) says nothing of the file's health.
bool is_damage(int rc) {
  const int primary = rc & 0xff;
  return primary == SQLITE_CORRUPT || primary == SQLITE_NOTADB;
}

// Why `file` cannot be written, for a writer's error: the file system, the file's or its folder's
// permissions.
std::string why_not_writable(const std::string& file) {
  const std::filesystem::path folder = std::filesystem::absolute(file).parent_path();
  struct statvfs fs {};
  if (::statvfs(folder.c_str(), &fs) == 0 && (fs.f_flag & ST_RDONLY)) return "its file system is mounted read-only";
  if (::access(file.c_str(), W_OK) != 0) return "this user may not write it";
  return "this user may not write its folder, where SQLite keeps the -wal and -shm files beside it";
}

}  // namespace

void SqliteConnection::open(int flags, const std::string& name) {
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
void SqliteConnection::check_integrity(bool writer) {
  std::string problem;  // quick_check's first line that is not "ok", or why SQLite could not run it
  auto first_problem = [](void* out, int, char** values, char**) {
    auto& text = *static_cast<std::string*>(out);
    if (text.empty() && values[0] != nullptr && std::string(values[0]) != "ok") text = values[0];
    return 0;
  };
  char* message = nullptr;
  if (const int rc = sqlite3_exec(db_, "PRAGMA quick_check", first_problem, &problem, &message); rc != SQLITE_OK) {
    problem = message ? message : sqlite3_errmsg(db_);  // the file itself refused: "file is not a database", ...
    sqlite3_free(message);
    if (!is_damage(sqlite3_extended_errcode(db_)))
      throw SessionStoreError(file_ + ": the session database could not be read (" + problem +
                              "): nothing says it is damaged" +
                              (writer ? "; " + why_not_writable(file_) + " (a run needs to write it)" : std::string()));
  }
  if (!problem.empty())
    throw SessionStoreError(file_ + ": the session database is damaged (PRAGMA quick_check: " + problem +
                            "); it was left as it is: restore a copy, or move it away to start a new one");
}

SqliteConnection::SqliteConnection(const std::string& file, bool read_only) : file_(file) {
  if (read_only) {
    open(SQLITE_OPEN_READONLY, file_);
  } else {
    open(SQLITE_OPEN_READWRITE | SQLITE_OPEN_CREATE, file_);
  }
  try {
    // A reader of a WAL database needs its -shm file. In a folder it cannot write, where none
    // exists (so no run is writing the file: a writer makes one), SQLite cannot open it for
    // reading; it then reads it as immutable, which needs no -shm.
    if (read_only && !std::filesystem::exists(file_ + "-shm") &&
        sqlite3_exec(db_, "SELECT 1 FROM sqlite_master LIMIT 1", nullptr, nullptr, nullptr) == SQLITE_CANTOPEN) {
      sqlite3_close(db_);
      db_ = nullptr;
      open(SQLITE_OPEN_READONLY | SQLITE_OPEN_URI, file_uri(file_, "immutable=1"));
    }
    // A file SQLite could open only for reading (a read-only file system, a file not ours) is
    // healthy as far as anyone knows: a writer is told why it cannot write, never that it is damaged.
    if (!read_only && sqlite3_db_readonly(db_, "main") == 1)
      throw SessionStoreError(file_ + ": the session database cannot be written: " + why_not_writable(file_) +
                              "; it is not damaged (needle-sim report and review read it as it is): a run needs a "
                              "database it can write (--db FILE)");
    check_integrity(!read_only);
    if (!read_only) {
      script("PRAGMA foreign_keys = ON", "");
      if (journal_mode() != "wal") {
        script("PRAGMA journal_mode = WAL", "");
        if (journal_mode() != "wal") throw SessionStoreError(file_ + ": cannot switch the journal to WAL");
      }
      script("PRAGMA synchronous = FULL", "");
    }
  } catch (...) {
    sqlite3_close(db_);
    throw;
  }
}

SqliteConnection::~SqliteConnection() { sqlite3_close(db_); }

SqlResult SqliteConnection::query(const std::string& sql, const std::vector<SqlValue>& params,
                                  const std::string& what) {
  const auto fail = [&](const char* step) -> void {
    throw SessionStoreError(file_ + ": " + what + ": " + step + ": " + sqlite3_errmsg(db_));
  };
  sqlite3_stmt* raw = nullptr;
  if (sqlite3_prepare_v2(db_, sql.c_str(), -1, &raw, nullptr) != SQLITE_OK) fail("preparing a statement");
  const std::unique_ptr<sqlite3_stmt, Finalize> stmt(raw);
  for (size_t i = 0; i < params.size(); ++i) {
    const int k = int(i + 1);
    const int rc = std::visit(
        [&](const auto& v) {
          using T = std::decay_t<decltype(v)>;
          if constexpr (std::is_same_v<T, SqlNull>)
            return sqlite3_bind_null(raw, k);
          else if constexpr (std::is_same_v<T, int64_t>)
            return sqlite3_bind_int64(raw, k, v);
          else if constexpr (std::is_same_v<T, double>)
            return std::isnan(v) ? sqlite3_bind_null(raw, k) : sqlite3_bind_double(raw, k, v);
          else if constexpr (std::is_same_v<T, std::string>)
            return sqlite3_bind_text(raw, k, v.data(), int(v.size()), SQLITE_TRANSIENT);
          else
            return sqlite3_bind_blob(raw, k, v.bytes.data(), int(v.bytes.size()), SQLITE_TRANSIENT);
        },
        params[i]);
    if (rc != SQLITE_OK) fail("binding a value");
  }
  SqlResult out;
  for (;;) {
    const int rc = sqlite3_step(raw);
    if (rc == SQLITE_DONE) break;
    if (rc != SQLITE_ROW) fail("running a statement");
    SqlRow row;
    for (int c = 0; c < sqlite3_column_count(raw); ++c) {
      switch (sqlite3_column_type(raw, c)) {
        case SQLITE_NULL:
          row.values.emplace_back(SqlNull{});
          break;
        case SQLITE_INTEGER:
          row.values.emplace_back(int64_t{sqlite3_column_int64(raw, c)});
          break;
        case SQLITE_FLOAT:
          row.values.emplace_back(sqlite3_column_double(raw, c));
          break;
        case SQLITE_BLOB: {
          const auto* p = static_cast<const char*>(sqlite3_column_blob(raw, c));
          row.values.emplace_back(SqlBlob{std::string(p, p + sqlite3_column_bytes(raw, c))});
          break;
        }
        default: {
          const auto* t = reinterpret_cast<const char*>(sqlite3_column_text(raw, c));
          row.values.emplace_back(std::string(t, t + sqlite3_column_bytes(raw, c)));
        }
      }
    }
    out.rows.push_back(std::move(row));
  }
  out.changes = sqlite3_changes(db_);
  return out;
}

void SqliteConnection::script(const std::string& sql, const std::string& what) {
  char* message = nullptr;
  if (sqlite3_exec(db_, sql.c_str(), nullptr, nullptr, &message) != SQLITE_OK) {
    const std::string text = message ? message : "unknown error";
    sqlite3_free(message);
    throw SessionStoreError(file_ + ": " + (what.empty() ? "running \"" + sql + "\"" : what) + ": " + text);
  }
}

void SqliteConnection::begin(bool write, const std::string& what) {
  const char* sql = write ? "BEGIN IMMEDIATE" : "BEGIN";
  if (sqlite3_exec(db_, sql, nullptr, nullptr, nullptr) != SQLITE_OK)
    throw SessionStoreError(file_ + ": " + what + ": " + sql + ": " + sqlite3_errmsg(db_));
}

void SqliteConnection::commit(const std::string& what) {
  if (sqlite3_exec(db_, "COMMIT", nullptr, nullptr, nullptr) != SQLITE_OK)
    throw SessionStoreError(file_ + ": " + what + ": COMMIT: " + sqlite3_errmsg(db_));
}

void SqliteConnection::rollback() noexcept { sqlite3_exec(db_, "ROLLBACK", nullptr, nullptr, nullptr); }

int SqliteConnection::user_version() {
  return int(query("PRAGMA user_version", {}, "reading the schema version").rows.at(0).integer(0));
}

void SqliteConnection::set_user_version(int version) {
  script("PRAGMA user_version = " + std::to_string(version),
         "setting the schema version");  // a number: no value from outside
}

std::string SqliteConnection::journal_mode() {
  return query("PRAGMA journal_mode", {}, "reading the journal mode").rows.at(0).text(0);
}

}  // namespace needle::training
