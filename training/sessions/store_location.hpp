// Where the session database is: an SQLite file, or a PostgreSQL server named by a libpq URI
// (postgresql://USER@HOST/DBNAME?sslmode=...; credentials also from PGPASSFILE or the environment,
// as libpq reads them). The URI is never shown with its password.
#pragma once

#include <string>

namespace needle::training {

// postgresql://... or postgres://... (libpq's two URI prefixes).
bool is_postgres_uri(const std::string& location);

// `location` as it may be printed or put in an error: a URI's password (user:PASSWORD@, or a
// password=... parameter) replaced by "***"; a file as it is.
std::string shown_location(const std::string& location);

}  // namespace needle::training
