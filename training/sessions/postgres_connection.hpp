// The session database on a PostgreSQL server, through libpq's C API (Debian libpq-dev): a URI
// as libpq takes it (credentials from it, PGPASSFILE or the environment; sslmode and the other
// TLS parameters passed through as written). One connection; `?` placeholders become $1, $2, ...
// and every value is sent apart from the SQL (PQsendQueryParams), so no value is ever parsed as
// SQL. Every wait on the server is bounded (below): a server that does not answer never hangs a run.
#pragma once

#include <memory>

#include "training/sessions/sql_connection.hpp"

struct pg_conn;
struct pg_result;

namespace needle::training {

// The store's waits on a server (docs/SESSIONS.md, "Timeouts"): design values for a training centre's
// network, where a server answers in milliseconds. A station waits at most kConnectSeconds before a run
// starts on without the server (a URI's own connect_timeout=N replaces it; 0 waits without limit, as
// libpq's); a statement the server has not answered in its statement_timeout (kStatementSeconds unless
// the URI's options, the role or the server set one) plus kAnswerMarginSeconds ends with the connection
// closed; TCP keepalives find a dead peer of an idle connection in kKeepaliveIdleSeconds +
// kKeepaliveCount x kKeepaliveIntervalSeconds, and data left unacknowledged for kTcpUserTimeoutSeconds
// ends it.
inline constexpr int kConnectSeconds = 5;       // half the 10 s a trainee may wait for a run to start
inline constexpr int kStatementSeconds = 30;    // the slowest statement: a migration or a cohort's read
inline constexpr int kAnswerMarginSeconds = 5;  // the server's own timeout speaks first
inline constexpr int kKeepaliveIdleSeconds = 10;
inline constexpr int kKeepaliveIntervalSeconds = 5;
inline constexpr int kKeepaliveCount = 3;
inline constexpr int kTcpUserTimeoutSeconds = 30;

// The server could not be reached at a host that exists: nothing accepted the connection (refused,
// no socket there) or nothing answered within the connect timeout. A run goes on without it (its
// session kept for needle-sim sync). Any other failure to connect (an unknown host, a certificate
// that does not verify, a password refused, a database the server lacks, a bad URI) is a plain
// SessionStoreError: to be fixed, never worked around.
struct ServerUnreachable : SessionStoreError {
  using SessionStoreError::SessionStoreError;
};

// The connection was lost after it was made (the server stopped or the network went, no answer
// within the statement's timeout): what the statement was to write is not on the server. A run
// keeps its session in this station's file for needle-sim sync, as when the server was unreachable
// at the start. A statement the server answered with a refusal is a plain SessionStoreError.
struct ServerLost : SessionStoreError {
  using SessionStoreError::SessionStoreError;
};

class PostgresConnection final : public SqlConnection {
 public:
  // Connects; `read_only` makes every transaction read-only (review, report). Throws
  // ServerUnreachable or SessionStoreError naming the URI without its password.
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
  // The statement's results once the server has sent them all: the first that failed, else the
  // last. No answer in the statement timeout and its margin closes the connection and throws.
  struct ClearResult {
    void operator()(pg_result* r) const;
  };
  using Result = std::unique_ptr<pg_result, ClearResult>;
  Result await(const std::string& what);

  std::string shown_;
  pg_conn* conn_ = nullptr;
  int answer_ms_ = (kStatementSeconds + kAnswerMarginSeconds) * 1000;
  std::string closed_;  // why the connection was closed (no answer in time); "" while open
};

// `sql` with its `?` placeholders numbered $1, $2, ... (a '?' inside '...' or "..." is kept).
std::string numbered_placeholders(const std::string& sql);

}  // namespace needle::training
