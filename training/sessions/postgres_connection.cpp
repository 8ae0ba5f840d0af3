#include "training/sessions/postgres_connection.hpp"

#include <libpq-fe.h>

#include <cmath>
#include <cstdio>
#include <memory>

#include "training/sessions/store_location.hpp"

namespace needle::training {

namespace {

struct ClearResult {
  void operator()(PGresult* r) const { PQclear(r); }
};
using Result = std::unique_ptr<PGresult, ClearResult>;

// Type OIDs (PostgreSQL's pg_type.dat): what a text-format column is read as.
constexpr Oid kBool = 16, kBytea = 17, kInt8 = 20, kInt2 = 21, kInt4 = 23, kFloat4 = 700, kFloat8 = 701, kNumeric = 1700;

int hex_digit(char c) { return c <= '9' ? c - '0' : (c | 0x20) - 'a' + 10; }

SqlValue column_value(const PGresult* r, int row, int c) {
  if (PQgetisnull(r, row, c)) return SqlNull{};
  const char* text = PQgetvalue(r, row, c);
  const int length = PQgetlength(r, row, c);
  switch (PQftype(r, c)) {
    case kInt8: case kInt2: case kInt4: return int64_t{std::strtoll(text, nullptr, 10)};
    case kBool: return int64_t{text[0] == 't'};
    case kFloat4: case kFloat8: case kNumeric: return std::strtod(text, nullptr);  // shortest exact text since PostgreSQL 12
    case kBytea: {  // hex output: \x then two digits a byte
      SqlBlob blob;
      blob.bytes.reserve(size_t(length) / 2);
      for (int i = 2; i + 1 < length; i += 2) blob.bytes += char(hex_digit(text[i]) * 16 + hex_digit(text[i + 1]));
      return blob;
    }
    default: return std::string(text, size_t(length));
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
  conn_ = PQconnectdb(uri.c_str());
  if (PQstatus(conn_) != CONNECTION_OK) {
    const std::string message = conn_ ? PQerrorMessage(conn_) : "out of memory";
    PQfinish(conn_);
    conn_ = nullptr;
    std::string trimmed = message.substr(0, message.find_last_not_of("\n ") + 1);
    throw SessionStoreError(shown_ + ": connecting to the session database: " + trimmed);
  }
  try {
    script("SET client_min_messages = warning", "setting up the connection");  // no NOTICE on stderr
    if (read_only) script("SET default_transaction_read_only = on", "making the connection read-only");
  } catch (...) {
    PQfinish(conn_);
    throw;
  }
}

PostgresConnection::~PostgresConnection() { PQfinish(conn_); }

void PostgresConnection::fail(const std::string& what) const {
  std::string message = PQerrorMessage(conn_);
  message = message.substr(0, message.find_last_not_of("\n ") + 1);
  throw SessionStoreError(shown_ + ": " + what + ": " + message);
}

SqlResult PostgresConnection::query(const std::string& sql, const std::vector<SqlValue>& params, const std::string& what) {
  std::vector<std::string> texts(params.size());
  std::vector<const char*> values(params.size(), nullptr);
  std::vector<int> lengths(params.size(), 0), formats(params.size(), 0);
  for (size_t i = 0; i < params.size(); ++i) {
    std::visit(
        [&](const auto& v) {
          using T = std::decay_t<decltype(v)>;
          if constexpr (std::is_same_v<T, SqlNull>) return;
          else if constexpr (std::is_same_v<T, int64_t>) texts[i] = std::to_string(v);
          else if constexpr (std::is_same_v<T, double>) {
            if (std::isnan(v)) return;
            char buffer[32];
            std::snprintf(buffer, sizeof buffer, "%.17g", v);  // round-trips every double
            texts[i] = buffer;
          } else if constexpr (std::is_same_v<T, std::string>) texts[i] = v;
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
  const Result r(PQexecParams(conn_, numbered.c_str(), int(params.size()), nullptr, values.data(), lengths.data(),
                              formats.data(), 0));
  const ExecStatusType status = PQresultStatus(r.get());
  if (status != PGRES_COMMAND_OK && status != PGRES_TUPLES_OK) fail(what);
  SqlResult out;
  for (int row = 0; row < PQntuples(r.get()); ++row) {
    SqlRow values_of_row;
    for (int c = 0; c < PQnfields(r.get()); ++c) values_of_row.values.push_back(column_value(r.get(), row, c));
    out.rows.push_back(std::move(values_of_row));
  }
  const char* changed = PQcmdTuples(r.get());
  out.changes = changed && *changed ? std::strtoll(changed, nullptr, 10) : 0;
  return out;
}

void PostgresConnection::script(const std::string& sql, const std::string& what) {
  const Result r(PQexec(conn_, sql.c_str()));
  if (PQresultStatus(r.get()) != PGRES_COMMAND_OK && PQresultStatus(r.get()) != PGRES_TUPLES_OK)
    fail(what.empty() ? "running \"" + sql + "\"" : what);
}

void PostgresConnection::begin(bool write, const std::string& what) {
  // A reader's snapshot: every query of the transaction sees the same committed state.
  script(write ? "BEGIN" : "BEGIN ISOLATION LEVEL REPEATABLE READ READ ONLY", what + ": BEGIN");
}

void PostgresConnection::commit(const std::string& what) { script("COMMIT", what + ": COMMIT"); }

void PostgresConnection::rollback() noexcept {
  if (PQstatus(conn_) != CONNECTION_OK) return;  // the server is gone: it rolled back
  PQclear(PQexec(conn_, "ROLLBACK"));
}

}  // namespace needle::training
