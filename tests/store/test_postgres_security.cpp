// PostgreSQL's security as docs/SESSIONS.md gives it: the roles of tools/postgres-roles.sql (a
// station reads and finishes only its own sessions, an instructor reads all and writes nothing),
// TLS settings passed to libpq as written, a URI's password never in a message.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <iterator>

#include "store_errors.hpp"
#include "tests/support/stored_sessions.hpp"
#include "tests/support/test_paths.hpp"
#include "tests/support/test_postgres.hpp"
#include "training/sessions/store_location.hpp"

namespace needle::training {
namespace {
namespace fs = std::filesystem;
using test::a_result;
using test::small_task;

TEST(PostgresRoles, AStationCannotSeeOrAlterAnotherStationsSessions) {
  const std::string owner_uri = test::fresh_postgres_database("t_roles");
  { SessionStore owner(owner_uri); }  // the owner's first open makes the schema
  const std::string roles = roles_sql();
  ASSERT_GT(roles.size(), 100u);
  test::postgres_admin(roles, "t_roles");
  test::postgres_admin(roles, "t_roles");  // idempotent
  test::postgres_admin(
      "DROP ROLE IF EXISTS \"station-a\"; DROP ROLE IF EXISTS \"station-b\"; DROP ROLE IF EXISTS \"dr-lee\";"
      "CREATE ROLE \"station-a\" LOGIN IN ROLE needle_station; CREATE ROLE \"station-b\" LOGIN IN ROLE needle_station;"
      "CREATE ROLE \"dr-lee\" LOGIN IN ROLE needle_instructor;");
  const std::string a_uri = test::postgres_uri("t_roles", "station-a");
  const std::string b_uri = test::postgres_uri("t_roles", "station-b");

  SessionStore a(a_uri), b(b_uri);
  const int64_t a_done = a.begin_session("ana", small_task(), "sim", "", "station-a");
  a.append_recording(a_done, 0, "abc");
  a.finish_session(a_done, a_result());
  const int64_t a_open = a.begin_session("ana", small_task(), "sim", "", "station-a");
  const int64_t b_own = b.begin_session("ben", small_task(), "sim", "", "station-b");
  b.finish_session(b_own, a_result());

  // Station b sees its own session only, cannot finish a's, nor add to its results or recording.
  ASSERT_EQ(b.sessions().size(), 1u);
  EXPECT_EQ(b.sessions()[0].id, b_own);
  EXPECT_NE(message_of([&] { b.finish_session(a_open, a_result()); }).find("no incomplete session with that id"),
            std::string::npos);
  EXPECT_NE(message_of([&] { b.append_recording(a_open, 0, "forged"); }), "");
  EXPECT_NE(message_of([&] { b.load(a_done); }).find("no such session"), std::string::npos);
  PostgresConnection b_raw(b_uri, false);
  EXPECT_EQ(b_raw.query("UPDATE sessions SET score = 100 WHERE id = ?", {a_done}, "").changes, 0);
  EXPECT_NE(
      message_of([&] { b_raw.query("DELETE FROM sessions WHERE id = ?", {a_done}, ""); }).find("permission denied"),
      std::string::npos);
  const std::string forged =
      message_of([&] { b_raw.query("INSERT INTO metrics VALUES (?, -1, 'forged', 1)", {a_done}, ""); });
  EXPECT_TRUE(forged.find("row-level security") != std::string::npos ||
              forged.find("permission denied") != std::string::npos)
      << forged;
  // Nor insert a session in another station's name.
  EXPECT_NE(
      message_of([&] { b.begin_session("ben", small_task(), "sim", "", "station-a"); }).find("row-level security"),
      std::string::npos);

  // a's sessions are as a left them; the instructor reads everything and can write nothing.
  SessionStore instructor(test::postgres_uri("t_roles", "dr-lee"), kReadOnly);
  ASSERT_EQ(instructor.sessions().size(), 3u);
  EXPECT_DOUBLE_EQ(instructor.load(a_done).info.score, a_result().score.total);
  EXPECT_EQ(instructor.load(a_done).steps.size(), 2u);
  EXPECT_EQ(instructor.recording(a_done), "abc");
  EXPECT_FALSE(instructor.load(a_open).info.complete);
  PostgresConnection lee(test::postgres_uri("t_roles", "dr-lee"), false);
  EXPECT_NE(message_of([&] { lee.query("UPDATE sessions SET score = 0", {}, ""); }).find("permission denied"),
            std::string::npos);
}

TEST(PostgresConnection, TlsSettingsArePassedToLibpqAsWritten) {
  // An sslmode libpq does not know is refused by libpq itself: the value reached it unchanged.
  const std::string error =
      message_of([] { PostgresConnection c(test::postgres_uri("postgres") + "&sslmode=bogus", false); });
  EXPECT_NE(error.find("sslmode"), std::string::npos) << error;
  EXPECT_NE(error.find("bogus"), std::string::npos) << error;
  // A value libpq refuses is a refusal to fix, never an outage to run through.
  EXPECT_THROW(PostgresConnection(test::postgres_uri("postgres") + "&sslmode=bogus", false), SessionStoreError);
  try {
    PostgresConnection c(test::postgres_uri("postgres") + "&sslmode=bogus", false);
  } catch (const ServerUnreachable&) {
    ADD_FAILURE() << "a bad sslmode taken for an unreachable server";
  } catch (const SessionStoreError&) {
  }
  // sslmode=disable over the socket connects (TLS is for TCP; libpq ignores it on a Unix socket).
  EXPECT_EQ(message_of([] { PostgresConnection c(test::postgres_uri("postgres") + "&sslmode=disable", false); }), "");
}

// What a run may go offline for: nothing there to answer (a socket folder without a server, a port
// nothing listens on). A server that answered and refused (a password, a database it lacks) is not.
TEST(PostgresConnection, OnlyAServerThatIsNotThereIsUnreachable) {
  const fs::path empty = test::output_dir() / "no_server_here";
  fs::create_directories(empty);
  EXPECT_THROW(PostgresConnection("postgresql:///postgres?host=" + empty.string(), false), ServerUnreachable);
  EXPECT_THROW(PostgresConnection("postgresql://needle@127.0.0.1:1/postgres", false), ServerUnreachable);
  // A password refused over the socket, whose connection is made at once.
  test::postgres_admin(
      "DO $$ BEGIN CREATE ROLE needle_password LOGIN PASSWORD 'right'; "
      "EXCEPTION WHEN duplicate_object THEN NULL; END $$");
  try {
    PostgresConnection c(test::postgres_uri("postgres", "needle_password") + "&password=wrong", false);
    ADD_FAILURE() << "connected with a wrong password";
  } catch (const ServerUnreachable& e) {
    ADD_FAILURE() << "a password refused taken for an unreachable server: " << e.what();
  } catch (const SessionStoreError& e) {
    EXPECT_NE(std::string(e.what()).find("password authentication failed"), std::string::npos) << e.what();
  }
  try {
    PostgresConnection c(test::postgres_uri("no_such_database"), false);
    ADD_FAILURE() << "connected to a database that does not exist";
  } catch (const ServerUnreachable& e) {
    ADD_FAILURE() << "a database the server lacks taken for an unreachable server: " << e.what();
  } catch (const SessionStoreError& e) {
    EXPECT_NE(std::string(e.what()).find("does not exist"), std::string::npos) << e.what();
  }
}

// Results come in binary, each column read by its type: every type the store's and its tests'
// queries return, against the values written in the SQL; a type it does not read is an error.
TEST(PostgresConnection, ColumnsAreReadByTheirTypesBinaryForm) {
  PostgresConnection c(test::postgres_uri("postgres"), true);
  const SqlRow row =
      c.query(
           "SELECT -2::int2, -70000::int4, -5000000000::int8, 4000000000::oid, true, false, 2.5::float4, "
           "-1.25e-300::float8, 12345678.0001::numeric, -0.0625::numeric, 0::numeric, 'text'::text, "
           "'name'::name, 'v'::varchar, 'c'::\"char\", '\\x00ff10'::bytea, NULL::numeric, ''::text",
           {}, "")
          .rows.at(0);
  EXPECT_EQ(row.integer(0), -2);
  EXPECT_EQ(row.integer(1), -70000);
  EXPECT_EQ(row.integer(2), -5000000000);
  EXPECT_EQ(row.integer(3), 4000000000);
  EXPECT_EQ(row.integer(4), 1);
  EXPECT_EQ(row.integer(5), 0);
  EXPECT_EQ(row.real(6), 2.5);
  EXPECT_EQ(row.real(7), -1.25e-300);
  EXPECT_DOUBLE_EQ(row.real(8), 12345678.0001);
  EXPECT_EQ(row.real(9), -0.0625);
  EXPECT_EQ(row.real(10), 0.0);
  EXPECT_EQ(row.text(11), "text");
  EXPECT_EQ(row.text(12), "name");
  EXPECT_EQ(row.text(13), "v");
  EXPECT_EQ(row.text(14), "c");
  EXPECT_EQ(row.blob(15), std::string("\x00\xff\x10", 3));
  EXPECT_TRUE(std::isnan(row.real(16)));
  EXPECT_EQ(row.text(17), "");
  const std::string error = message_of([&] { c.query("SELECT now() AS started", {}, "reading the clock"); });
  EXPECT_NE(error.find("reading the clock: column started is of a type the store does not read (OID 1184)"),
            std::string::npos)
      << error;
}

TEST(StoreLocation, APasswordIsNeverShown) {
  EXPECT_EQ(shown_location("postgresql://station:pw@db.lab/needle?sslmode=verify-full"),
            "postgresql://station:***@db.lab/needle?sslmode=verify-full");
  EXPECT_EQ(shown_location("postgres://u:p%40ss@h:5432/d"), "postgres://u:***@h:5432/d");
  EXPECT_EQ(shown_location("postgresql:///needle?host=/run/pg&password=hunter2&user=x"),
            "postgresql:///needle?host=/run/pg&password=***&user=x");
  EXPECT_EQ(shown_location("postgresql://u@h/d?password=x"), "postgresql://u@h/d?password=***");
  EXPECT_EQ(shown_location("postgresql://h/d"), "postgresql://h/d");
  EXPECT_EQ(shown_location("/home/ana/sessions:db@x.db"), "/home/ana/sessions:db@x.db");  // a file is a file
  // A message of a failed connection names the server without the password.
  const std::string error =
      message_of([] { SessionStore s("postgresql://needle:hunter2@/no_such_database?host=" + test::postgres_dir()); });
  EXPECT_NE(error.find("postgresql://needle:***@/no_such_database"), std::string::npos) << error;
  EXPECT_EQ(error.find("hunter2"), std::string::npos) << error;
}

}  // namespace
}  // namespace needle::training
