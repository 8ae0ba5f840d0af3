// The throwaway PostgreSQL cluster tests/support/with-postgres.sh runs beside a test program: a
// fresh database per test, the server stopped and started as a test needs.
#pragma once

#include <cstdlib>
#include <stdexcept>
#include <string>

#include "training/sessions/postgres_connection.hpp"

namespace needle::test {

// The socket folder with-postgres.sh made; "" when the program runs without it.
inline std::string postgres_dir() {
  const char* dir = std::getenv("NEEDLE_TEST_PG_DIR");
  return dir ? dir : "";
}

// A URI for `database` on the test cluster, as `user`.
inline std::string postgres_uri(const std::string& database, const std::string& user = "needle") {
  return "postgresql:///" + database + "?host=" + postgres_dir() + "&user=" + user;
}

// Runs SQL on the cluster's maintenance database as its superuser.
inline void postgres_admin(const std::string& sql, const std::string& database = "postgres") {
  training::PostgresConnection admin(postgres_uri(database), false);
  admin.script(sql, "test set-up");
}

// Makes an empty database `name` (dropping one of that name) and returns its URI. `name` is a
// test's own identifier (letters, digits, '_').
inline std::string fresh_postgres_database(const std::string& name) {
  postgres_admin("DROP DATABASE IF EXISTS " + name + " WITH (FORCE)");
  postgres_admin("CREATE DATABASE " + name);
  return postgres_uri(name);
}

// Stops the server as if it died (immediate), or starts it again.
inline void postgres_server(const char* action) {
  if (std::system((postgres_dir() + "/ctl " + action).c_str()) != 0)
    throw std::runtime_error(std::string("the test cluster did not ") + action);
}

}  // namespace needle::test
