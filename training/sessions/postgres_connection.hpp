// The session database on a PostgreSQL server, through libpq's C API (Debian libpq-dev): a URI
// as libpq takes it (credentials from it, PGPASSFILE or the environment; sslmode and the other
// TLS parameters passed through as written). One connection; `?` placeholders become $1, $2, ...
// and every value is sent apart from the SQL (PQexecParams), so no value is ever parsed as SQL.
#pragma once

#include "training/sessions/sql_connection.hpp"

struct pg_conn;

namespace needle::training {

class PostgresConnection final : public SqlConnection {
 public:
  // Connects; `read_only` makes every transaction read-only (review, report). Throws
  // SessionStoreError naming the URI without its password.
  PostgresConnection(const std::string& uri, bool read_only);
  ~PostgresConnection() override;
  PostgresConnection(const PostgresConnection&) = delete;
  PostgresConnection& operator=(const PostgresConnection&) = delete;

  SqlEngine engine() const override { return SqlEngine::kPostgres; }
  const std::string& name() const override { return shown_; }
  SqlResult query(const std::string& sql, const std::vector<SqlValue>& params, const std::string& what) override;
  void script(const std::string& sql, const std::string& what) override;
  void begin(bool write, const std::string& what) override;
  void commit(const std::string& what) override;
  void rollback() noexcept override;

 private:
  [[noreturn]] void fail(const std::string& what) const;

  std::string shown_;
  pg_conn* conn_ = nullptr;
};

// `sql` with its `?` placeholders numbered $1, $2, ... (a '?' inside '...' or "..." is kept).
std::string numbered_placeholders(const std::string& sql);

}  // namespace needle::training
