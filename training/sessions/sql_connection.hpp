// One connection to the session database, whichever engine holds it (SQLite or PostgreSQL): the
// store's SQL is written once, with `?` placeholders, and every value travels as a parameter
// (no string-built SQL). A query fetches all its rows; the store's queries return few.
#pragma once

#include <cstdint>
#include <memory>
#include <stdexcept>
#include <string>
#include <variant>
#include <vector>

namespace needle::training {

// "DATABASE: what failed: the engine's message" (DATABASE: the file, or the URI without password).
struct SessionStoreError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// A stored value no run stores (a score outside 0-100): the store was damaged or altered.
struct StoredValueError : SessionStoreError {
  using SessionStoreError::SessionStoreError;
};

struct SqlNull {};
struct SqlBlob {
  std::string bytes;  // raw bytes (a recording's chunk)
};
// A parameter or a column's value. A NaN double is sent as NULL (a metric that does not apply).
using SqlValue = std::variant<SqlNull, int64_t, double, std::string, SqlBlob>;

struct SqlRow {
  std::vector<SqlValue> values;
  double real(size_t c) const;       // NULL: NaN
  int64_t integer(size_t c) const;   // NULL: 0
  std::string text(size_t c) const;  // NULL: ""
  const std::string& blob(size_t c) const;
};

struct SqlResult {
  std::vector<SqlRow> rows;
  int64_t changes = 0;  // rows an INSERT, UPDATE or DELETE changed
};

enum class SqlEngine { kSqlite, kPostgres };

class SqlConnection {
 public:
  virtual ~SqlConnection() = default;
  virtual SqlEngine engine() const = 0;
  // The database as it may be shown: the file, or the URI without its password.
  virtual const std::string& name() const = 0;
  // Runs `sql` (one statement, `?` placeholders) with `params`; errors read "NAME: what: message".
  virtual SqlResult query(const std::string& sql, const std::vector<SqlValue>& params, const std::string& what) = 0;
  // Runs statements without parameters (a migration).
  virtual void script(const std::string& sql, const std::string& what) = 0;
  // BEGIN for a write (SQLite: IMMEDIATE, taking the write lock at once) or a read snapshot
  // (PostgreSQL: REPEATABLE READ), COMMIT, ROLLBACK (never throws).
  virtual void begin(bool write, const std::string& what) = 0;
  virtual void commit(const std::string& what) = 0;
  virtual void rollback() noexcept = 0;
};

// BEGIN on construction, ROLLBACK on destruction unless commit() ran: an exception anywhere in
// between leaves the database as it was.
class SqlTransaction {
 public:
  SqlTransaction(SqlConnection& db, std::string what, bool write = true) : db_(db), what_(std::move(what)) {
    db_.begin(write, what_);
  }
  ~SqlTransaction() {
    if (open_) db_.rollback();
  }
  SqlTransaction(const SqlTransaction&) = delete;
  SqlTransaction& operator=(const SqlTransaction&) = delete;
  void commit() {
    db_.commit(what_);
    open_ = false;
  }

 private:
  SqlConnection& db_;
  std::string what_;
  bool open_ = true;
};

}  // namespace needle::training
