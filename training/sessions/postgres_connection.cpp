#include "training/sessions/postgres_connection.hpp"

#include <libpq-fe.h>
#include <netdb.h>
#include <poll.h>

#include <bit>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <optional>
#include <vector>

#include "training/sessions/store_location.hpp"

namespace needle::training {

namespace {

using Clock = std::chrono::steady_clock;

bool succeeded(const PGresult* r) {
  const ExecStatusType status = PQresultStatus(r);
  return status == PGRES_COMMAND_OK || status == PGRES_TUPLES_OK;
}

// libpq's message on one line: its trailing newline dropped, the lines of a message of several (a
// host tried at each of its addresses, a hint) joined with "; ".
std::string trimmed(const std::string& message) {
  const std::string text = message.substr(0, message.find_last_not_of("\n\t ") + 1);
  std::string out;
  for (size_t i = 0; i < text.size(); ++i) {
    if (text[i] != '\n') {
      out += text[i];
      continue;
    }
    out += "; ";
    while (i + 1 < text.size() && (text[i + 1] == '\t' || text[i + 1] == ' ')) ++i;
  }
  return out;
}

// Waits until `socket` can be written (`write`) or read, or `deadline` passes (false). A deadline of
// Clock::time_point::max() waits without limit.
bool wait_for(int socket, bool write, Clock::time_point deadline) {
  pollfd p{socket, short(write ? POLLOUT : POLLIN), 0};
  for (;;) {
    int timeout_ms = -1;
    if (deadline != Clock::time_point::max()) {
      const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now()).count();
      if (left <= 0) return false;
      timeout_ms = int(std::min<int64_t>(left, 1 << 30));
    }
    const int n = ::poll(&p, 1, timeout_ms);
    if (n > 0) return true;
    if (n < 0 && errno != EINTR) return true;  // libpq's next call reports what is wrong with the socket
  }
}

// The value of libpq option `keyword` as `uri` sets it, else the environment variable `env`, else "".
std::string option(const PQconninfoOption* options, const char* keyword, const char* env) {
  for (const PQconninfoOption* o = options; o && o->keyword; ++o)
    if (std::string(o->keyword) == keyword && o->val && *o->val) return o->val;
  const char* value = std::getenv(env);
  return value ? value : "";
}

// Connects to `uri` (shown as `shown`) within its connect timeout. Every host named must resolve
// (an unknown host is an error to fix); a connection then refused, or not answered in time, is
// ServerUnreachable; any failure after the server answered (TLS, authentication, the database) is
// SessionStoreError.
pg_conn* open_connection(const std::string& uri, const std::string& shown) {
  const std::string connecting = shown + ": connecting to the session database: ";
  char* parse_error = nullptr;
  PQconninfoOption* options = PQconninfoParse(uri.c_str(), &parse_error);
  if (!options) {
    const std::string why = parse_error ? trimmed(parse_error) : "out of memory";
    PQfreemem(parse_error);
    throw SessionStoreError(connecting + why);
  }
  const std::string hosts = option(options, "host", "PGHOST"), hostaddr = option(options, "hostaddr", "PGHOSTADDR");
  const std::string timeout_text = option(options, "connect_timeout", "PGCONNECT_TIMEOUT");
  PQconninfoFree(options);
  if (hostaddr.empty()) {  // a host name is looked up (a socket folder, '/...' or '@...', is not)
    for (size_t at = 0; at <= hosts.size();) {
      const size_t comma = std::min(hosts.find(',', at), hosts.size());
      const std::string host = hosts.substr(at, comma - at);
      at = comma + 1;
      if (host.empty() || host[0] == '/' || host[0] == '@') continue;
      addrinfo hints{};
      hints.ai_socktype = SOCK_STREAM;
      addrinfo* found = nullptr;
      const int rc = ::getaddrinfo(host.c_str(), nullptr, &hints, &found);
      if (found) ::freeaddrinfo(found);
      if (rc != 0) throw SessionStoreError(connecting + "unknown host \"" + host + "\" (" + ::gai_strerror(rc) + ")");
    }
  }
  // libpq treats 1 as 2 and 0 as no limit.
  const int timeout_s = timeout_text.empty()                   ? kConnectSeconds
                        : std::atoi(timeout_text.c_str()) == 1 ? 2
                                                               : std::atoi(timeout_text.c_str());
  const Clock::time_point deadline =
      timeout_s > 0 ? Clock::now() + std::chrono::seconds(timeout_s) : Clock::time_point::max();
  // The store's defaults first, the URI after them: what the URI sets wins.
  const std::string defaults[][2] = {{"connect_timeout", std::to_string(kConnectSeconds)},
                                     {"keepalives", "1"},
                                     {"keepalives_idle", std::to_string(kKeepaliveIdleSeconds)},
                                     {"keepalives_interval", std::to_string(kKeepaliveIntervalSeconds)},
                                     {"keepalives_count", std::to_string(kKeepaliveCount)},
                                     {"tcp_user_timeout", std::to_string(kTcpUserTimeoutSeconds * 1000)}};
  std::vector<const char*> keywords, values;
  for (const auto& [k, v] : defaults) keywords.push_back(k.c_str()), values.push_back(v.c_str());
  keywords.push_back("dbname");
  values.push_back(uri.c_str());
  keywords.push_back(nullptr);
  values.push_back(nullptr);
  pg_conn* conn = PQconnectStartParams(keywords.data(), values.data(), 1);
  if (!conn) throw SessionStoreError(connecting + "out of memory");
  if (PQstatus(conn) == CONNECTION_BAD) {
    // Failed before any wait: a value libpq does not take (sslmode=bogus), or the connection itself
    // (no socket there, a port refused) tried at once, which no server could have answered yet.
    // libpq names the second "connection to server ..." (its messages are English: this program
    // sets no locale).
    const std::string why = trimmed(PQerrorMessage(conn));
    PQfinish(conn);
    if (why.rfind("connection to server", 0) == 0) throw ServerUnreachable(connecting + why);
    throw SessionStoreError(connecting + why);
  }
  // Whether a server answered: libpq got past making the connection (the TCP handshake or the
  // socket's connect) at least once.
  const auto made = [](ConnStatusType status) {
    return status != CONNECTION_STARTED && status != CONNECTION_NEEDED && status != CONNECTION_BAD;
  };
  bool answered = made(PQstatus(conn));  // a socket's connect is made at once, in PQconnectStartParams
  PostgresPollingStatusType polled = PGRES_POLLING_WRITING;
  while (polled != PGRES_POLLING_OK && polled != PGRES_POLLING_FAILED) {
    if (PQsocket(conn) >= 0 && !wait_for(PQsocket(conn), polled == PGRES_POLLING_WRITING, deadline)) {
      PQfinish(conn);
      throw ServerUnreachable(connecting + "no answer within " + std::to_string(timeout_s) + " s (connect_timeout)");
    }
    polled = PQconnectPoll(conn);
    answered = answered || made(PQstatus(conn));
  }
  if (polled == PGRES_POLLING_OK) return conn;
  const std::string why = trimmed(PQerrorMessage(conn));
  PQfinish(conn);
  if (!answered) throw ServerUnreachable(connecting + why);
  throw SessionStoreError(connecting + why);
}

// Type OIDs (PostgreSQL's pg_type.dat) of the columns the store reads. Results come in binary (a
// recording's bytes as they are, half the hex text's size, nothing to decode): each column is read
// by its type, and a type not here is an error, never bytes taken for something else.
constexpr Oid kBool = 16, kBytea = 17, kChar = 18, kName = 19, kInt8 = 20, kInt2 = 21, kInt4 = 23, kText = 25,
              kOid = 26, kFloat4 = 700, kFloat8 = 701, kBpchar = 1042, kVarchar = 1043, kNumeric = 1700, kVoid = 2278;

// A big-endian (network order) unsigned integer of `bytes` bytes at `p`.
uint64_t big_endian(const char* p, int bytes) {
  uint64_t v = 0;
  for (int i = 0; i < bytes; ++i) v = (v << 8) | static_cast<unsigned char>(p[i]);
  return v;
}

// NUMERIC's binary form: digit count, weight (of the first digit, a power of 10000), sign, display
// scale, then the base-10000 digits.
double numeric_value(const char* p, int length) {
  if (length < 8) return std::nan("");
  const int count = int(big_endian(p, 2)), weight = int(int16_t(big_endian(p + 2, 2))),
            sign = int(big_endian(p + 4, 2));
  if (sign == 0xC000 || length < 8 + 2 * count) return std::nan("");
  double v = 0.0;
  for (int i = 0; i < count; ++i) v += double(big_endian(p + 8 + 2 * i, 2)) * std::pow(10000.0, weight - i);
  return sign == 0x4000 ? -v : v;
}

// Column `c` of `row`, read as its type's binary form; nullopt for a type the store does not read.
std::optional<SqlValue> column_value(const PGresult* r, int row, int c) {
  if (PQgetisnull(r, row, c)) return SqlValue{SqlNull{}};
  const char* p = PQgetvalue(r, row, c);
  const int length = PQgetlength(r, row, c);
  switch (PQftype(r, c)) {
    case kInt8:
      return SqlValue{int64_t(big_endian(p, 8))};
    case kInt4:
      return SqlValue{int64_t{int32_t(uint32_t(big_endian(p, 4)))}};
    case kInt2:
      return SqlValue{int64_t{int16_t(uint16_t(big_endian(p, 2)))}};
    case kOid:
      return SqlValue{int64_t(big_endian(p, 4))};
    case kBool:
      return SqlValue{int64_t{p[0] != 0}};
    case kFloat8:
      return SqlValue{std::bit_cast<double>(big_endian(p, 8))};
    case kFloat4:
      return SqlValue{double(std::bit_cast<float>(uint32_t(big_endian(p, 4))))};
    case kNumeric:
      return SqlValue{numeric_value(p, length)};
    case kBytea:
      return SqlValue{SqlBlob{std::string(p, size_t(length))}};
    case kText:
    case kName:
    case kChar:
    case kBpchar:
    case kVarchar:
      return SqlValue{std::string(p, size_t(length))};
    case kVoid:
      return SqlValue{SqlNull{}};
    default:
      return std::nullopt;
  }
}

}  // namespace

std::string numbered_placeholders(const std::string& sql) {
  std::string out;
  int n = 0;
  char quote = 0;
  for (const char c : sql) {
    if (quote) {
      if (c == quote) quote = 0;
      out += c;
    } else if (c == '\'' || c == '"') {
      quote = c;
      out += c;
    } else if (c == '?') {
      out += "$" + std::to_string(++n);
    } else {
      out += c;
    }
  }
  return out;
}

PostgresConnection::PostgresConnection(const std::string& uri, bool read_only) : shown_(shown_location(uri)) {
  conn_ = open_connection(uri, shown_);
  try {
    script("SET client_min_messages = warning", "setting up the connection");  // no NOTICE on stderr
    // The server's statement timeout, unless the URI's options, the role or the server set one; the
    // client waits that long and its margin for any answer.
    const SqlResult set =
        query("SELECT setting FROM pg_settings WHERE name = 'statement_timeout'", {}, "reading the statement timeout");
    int64_t ms = set.rows.empty() ? 0 : std::strtoll(set.rows[0].text(0).c_str(), nullptr, 10);
    if (ms <= 0) {
      ms = kStatementSeconds * 1000;
      script("SET statement_timeout = " + std::to_string(ms), "setting the statement timeout");  // a number of ours
    }
    answer_ms_ = int(std::min<int64_t>(ms + kAnswerMarginSeconds * 1000, 24 * 3600 * 1000));
    if (read_only) script("SET default_transaction_read_only = on", "making the connection read-only");
  } catch (...) {
    PQfinish(conn_);
    throw;
  }
}

PostgresConnection::~PostgresConnection() { PQfinish(conn_); }

void PostgresConnection::ClearResult::operator()(pg_result* r) const { PQclear(r); }

void PostgresConnection::fail(const std::string& what) const {
  if (!closed_.empty()) throw ServerLost(shown_ + ": " + what + ": " + closed_);
  if (PQstatus(conn_) == CONNECTION_BAD) throw ServerLost(shown_ + ": " + what + ": " + trimmed(PQerrorMessage(conn_)));
  throw SessionStoreError(shown_ + ": " + what + ": " + trimmed(PQerrorMessage(conn_)));
}

PostgresConnection::Result PostgresConnection::await(const std::string& what) {
  const Clock::time_point deadline = Clock::now() + std::chrono::milliseconds(answer_ms_);
  Result kept;  // the first result that failed, else the last
  bool kept_failed = false;
  for (;;) {
    while (PQisBusy(conn_)) {
      if (!wait_for(PQsocket(conn_), false, deadline)) {
        PQfinish(conn_);
        conn_ = nullptr;
        closed_ = "no answer from the server within " + std::to_string(answer_ms_ / 1000) +
                  " s (its statement timeout and a margin): the connection was closed";
        fail(what);
      }
      if (!PQconsumeInput(conn_)) fail(what);
    }
    Result r(PQgetResult(conn_));
    if (!r) return kept;
    if (kept_failed) continue;
    kept_failed = !succeeded(r.get());
    kept = std::move(r);
  }
}

SqlResult PostgresConnection::query(const std::string& sql, const std::vector<SqlValue>& params,
                                    const std::string& what) {
  std::vector<std::string> texts(params.size());
  std::vector<const char*> values(params.size(), nullptr);
  std::vector<int> lengths(params.size(), 0), formats(params.size(), 0);
  for (size_t i = 0; i < params.size(); ++i) {
    std::visit(
        [&](const auto& v) {
          using T = std::decay_t<decltype(v)>;
          if constexpr (std::is_same_v<T, SqlNull>)
            return;
          else if constexpr (std::is_same_v<T, int64_t>)
            texts[i] = std::to_string(v);
          else if constexpr (std::is_same_v<T, double>) {
            if (std::isnan(v)) return;
            char buffer[32];
            std::snprintf(buffer, sizeof buffer, "%.17g", v);  // round-trips every double
            texts[i] = buffer;
          } else if constexpr (std::is_same_v<T, std::string>)
            texts[i] = v;
          else {
            texts[i] = v.bytes;
            formats[i] = 1;  // binary: the bytes as they are
          }
          values[i] = texts[i].data();
          lengths[i] = int(texts[i].size());
        },
        params[i]);
  }
  const std::string numbered = numbered_placeholders(sql);
  if (!PQsendQueryParams(conn_, numbered.c_str(), int(params.size()), nullptr, values.data(), lengths.data(),
                         formats.data(), 1))
    fail(what);
  const Result r = await(what);
  if (!succeeded(r.get())) fail(what);
  SqlResult out;
  for (int row = 0; row < PQntuples(r.get()); ++row) {
    SqlRow values_of_row;
    for (int c = 0; c < PQnfields(r.get()); ++c) {
      std::optional<SqlValue> value = column_value(r.get(), row, c);
      if (!value)
        throw SessionStoreError(shown_ + ": " + what + ": column " + PQfname(r.get(), c) +
                                " is of a type the store does not read (OID " + std::to_string(PQftype(r.get(), c)) +
                                ")");
      values_of_row.values.push_back(std::move(*value));
    }
    out.rows.push_back(std::move(values_of_row));
  }
  const char* changed = PQcmdTuples(r.get());
  out.changes = changed && *changed ? std::strtoll(changed, nullptr, 10) : 0;
  return out;
}

void PostgresConnection::script(const std::string& sql, const std::string& what) {
  const std::string doing = what.empty() ? "running \"" + sql + "\"" : what;
  if (!PQsendQuery(conn_, sql.c_str())) fail(doing);
  const Result r = await(doing);
  if (!succeeded(r.get())) fail(doing);
}

void PostgresConnection::begin(bool write, const std::string& what) {
  // A reader's snapshot: every query of the transaction sees the same committed state.
  script(write ? "BEGIN" : "BEGIN ISOLATION LEVEL REPEATABLE READ READ ONLY", what + ": BEGIN");
}

void PostgresConnection::commit(const std::string& what) { script("COMMIT", what + ": COMMIT"); }

void PostgresConnection::rollback() noexcept {
  if (PQstatus(conn_) != CONNECTION_OK) return;  // the server is gone (or no answer closed it): it rolled back
  try {
    script("ROLLBACK", "ROLLBACK");
  } catch (const SessionStoreError&) {  // gone meanwhile: the server rolls back what it had
  }
}

}  // namespace needle::training
