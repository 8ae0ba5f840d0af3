// The session database's schema and its migrations, for both engines (docs/SESSIONS.md, "Schema").
// Version N means migrations 1..N ran; SQLite keeps N in PRAGMA user_version, PostgreSQL in the
// one-row table needle_schema. The two engines get the same tables and columns, each in its own
// types (SQLite INTEGER PRIMARY KEY and REAL, PostgreSQL identity columns and double precision).
#pragma once

#include "training/sessions/sql_connection.hpp"

namespace needle::training {

inline constexpr int kSessionSchemaVersion = 4;

// The database's schema version; 0 for an empty database (nothing of ours in it).
int schema_version(SqlConnection& db);

// Applies the migrations from the database's version up to `target` in one transaction, under the
// engine's write lock (SQLite: BEGIN IMMEDIATE; PostgreSQL: an advisory lock), re-reading the
// version inside it: two programs opening an old database at once migrate it once. Refuses a
// database newer than this program, untouched.
void migrate_schema(SqlConnection& db, int target);

// Refuses, naming the database, a database that has no schema (read-only opens cannot make one)
// or a newer one than this program's.
void check_schema_readable(SqlConnection& db);

}  // namespace needle::training
