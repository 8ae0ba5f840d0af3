// The session database in an SQLite file (docs/SESSIONS.md): WAL journal, synchronous FULL,
// foreign keys, a 10 s busy timeout; checked (PRAGMA quick_check) before anything reads it.
#pragma once

#include "training/sessions/sql_connection.hpp"

struct sqlite3;

namespace needle::training {

class SqliteConnection final : public SqlConnection {
 public:
  // Opens (creating it unless `read_only`) and checks `file`; a damaged file is refused, untouched.
  SqliteConnection(const std::string& file, bool read_only);
  ~SqliteConnection() override;
  SqliteConnection(const SqliteConnection&) = delete;
  SqliteConnection& operator=(const SqliteConnection&) = delete;

  SqlEngine engine() const override { return SqlEngine::kSqlite; }
  const std::string& name() const override { return file_; }
  SqlResult query(const std::string& sql, const std::vector<SqlValue>& params, const std::string& what) override;
  void script(const std::string& sql, const std::string& what) override;
  void begin(bool write, const std::string& what) override;
  void commit(const std::string& what) override;
  void rollback() noexcept override;

  int user_version();
  void set_user_version(int version);
  std::string journal_mode();

 private:
  void open(int flags, const std::string& name);  // name: the file, or an SQLite URI for it
  void check_integrity(bool writer);

  std::string file_;
  sqlite3* db_ = nullptr;
};

}  // namespace needle::training
