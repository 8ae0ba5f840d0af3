// tools/postgres-roles.sql as docs/SESSIONS.md tells a centre to run it: by the database's owner, a
// plain role with CREATEROLE (no superuser). It installs whole (every grant and policy checked
// against the list below) or, without what it needs, not at all and says what is missing. Then, as
// each role: every tampering statement a station could try fails with a permission error, a
// station works on its own sessions as a run does, an instructor reads all, renames a trainee
// (logged under its role) and keeps checks in its own name only.
#include <gtest/gtest.h>

#include <fstream>
#include <iterator>
#include <set>
#include <tuple>

#include "store_errors.hpp"
#include "tests/support/stored_sessions.hpp"
#include "tests/support/test_paths.hpp"
#include "tests/support/test_postgres.hpp"

namespace needle::training {
namespace {
using test::a_result;
using test::small_task;

// A database owned by a new login `owner` (CREATEROLE when `createrole`, never a superuser), with
// the schema its owner's first open makes when `schema`. Returns the owner's URI.
std::string owned_database(const std::string& name, const std::string& owner, bool createrole, bool schema = true) {
  test::postgres_admin("DROP DATABASE IF EXISTS " + name + " WITH (FORCE)");
  test::postgres_admin("DO $$ BEGIN CREATE ROLE " + owner + " LOGIN" + (createrole ? " CREATEROLE" : "") +
                       "; EXCEPTION WHEN duplicate_object THEN NULL; END $$");
  test::postgres_admin("CREATE DATABASE " + name + " OWNER " + owner);
  const std::string uri = test::postgres_uri(name, owner);
  if (schema) SessionStore make(uri);
  return uri;
}

using Grant = std::tuple<std::string, std::string, std::string>;  // (object, role, privilege)

// Every privilege the two roles hold on this database's tables and sequences (`columns`: on single
// columns, "table.column"), from the catalog's access lists.
std::set<Grant> grants(PostgresConnection& c, bool columns) {
  const std::string sql =
      columns
          ? "SELECT c.relname || '.' || a.attname, r.rolname, x.privilege_type FROM pg_attribute a "
            "JOIN pg_class c ON c.oid = a.attrelid CROSS JOIN aclexplode(a.attacl) x JOIN pg_roles r ON r.oid = "
            "x.grantee "
            "WHERE c.relnamespace = 'public'::regnamespace AND r.rolname IN ('needle_station', 'needle_instructor')"
          : "SELECT c.relname, r.rolname, x.privilege_type FROM pg_class c CROSS JOIN aclexplode(c.relacl) x "
            "JOIN pg_roles r ON r.oid = x.grantee "
            "WHERE c.relnamespace = 'public'::regnamespace AND r.rolname IN ('needle_station', 'needle_instructor')";
  std::set<Grant> out;
  for (const SqlRow& row : c.query(sql, {}, "reading grants").rows) out.insert({row.text(0), row.text(1), row.text(2)});
  return out;
}

std::set<Grant> expected_table_grants() {
  std::set<Grant> g;
  for (const char* t : {"needle_schema", "trainees", "tasks", "sessions", "step_results", "metrics", "score_components",
                        "recording_chunks", "session_checks"})
    for (const char* role : {"needle_station", "needle_instructor"}) g.insert({t, role, "SELECT"});
  for (const char* t :
       {"trainees", "tasks", "sessions", "step_results", "metrics", "score_components", "recording_chunks"})
    g.insert({t, "needle_station", "INSERT"});
  for (const char* s : {"trainees_id_seq", "tasks_id_seq", "sessions_id_seq"}) g.insert({s, "needle_station", "USAGE"});
  g.insert({"trainee_renames", "needle_instructor", "SELECT"});
  g.insert({"session_checks", "needle_instructor", "INSERT"});
  g.insert({"session_checks_id_seq", "needle_instructor", "USAGE"});
  return g;
}

std::set<Grant> expected_column_grants() {
  std::set<Grant> g;
  for (const char* c : {"status", "ended_at", "score", "passed", "duration_s"})
    g.insert({std::string("sessions.") + c, "needle_station", "UPDATE"});
  g.insert({"trainees.name", "needle_instructor", "UPDATE"});
  return g;
}

using Policy = std::tuple<std::string, std::string, std::string, std::string>;  // (table, name, command, roles)

std::set<Policy> policies(PostgresConnection& c) {
  std::set<Policy> out;
  for (const SqlRow& row : c.query("SELECT tablename, policyname, cmd, array_to_string(roles, ',') FROM pg_policies "
                                   "WHERE schemaname = 'public'",
                                   {}, "reading policies")
                               .rows)
    out.insert({row.text(0), row.text(1), row.text(2), row.text(3)});
  return out;
}

std::set<Policy> expected_policies() {
  std::set<Policy> p;
  for (const char* t :
       {"sessions", "step_results", "metrics", "score_components", "recording_chunks", "session_checks"}) {
    p.insert({t, "instructor_reads", "SELECT", "needle_instructor"});
    p.insert({t, "station_reads", "SELECT", "needle_station"});
  }
  for (const char* t : {"step_results", "metrics", "score_components", "recording_chunks"})
    p.insert({t, "station_appends", "INSERT", "needle_station"});
  p.insert({"sessions", "station_begins", "INSERT", "needle_station"});
  p.insert({"sessions", "station_finishes", "UPDATE", "needle_station"});
  p.insert({"session_checks", "instructor_checks", "INSERT", "needle_instructor"});
  return p;
}

// One database for the suite, installed by its plain owner, with two stations and an instructor.
class PostgresRoleScript : public testing::Test {
 protected:
  static void SetUpTestSuite() {
    owner_ = owned_database("t_role_script", "centre_owner", true);
    PostgresConnection owner(owner_, false);
    owner.script(roles_sql(), "applying the roles");
    owner.script(roles_sql(), "applying the roles again");  // the same result (checked below)
    owner.script(
        "DO $$ BEGIN CREATE ROLE \"station-01\" LOGIN IN ROLE needle_station; "
        "CREATE ROLE \"station-02\" LOGIN IN ROLE needle_station; "
        "CREATE ROLE \"dr-lee\" LOGIN IN ROLE needle_instructor; "
        "EXCEPTION WHEN duplicate_object THEN NULL; END $$",
        "making the logins");
    // A session of each station: station-01's finished (alice's), station-02's open (bob's).
    SessionStore one(uri("station-01")), two(uri("station-02"));
    done_ = one.begin_session("alice", small_task(), "sim", "", "station-01");
    one.append_recording(done_, 0, "abc");
    one.finish_session(done_, a_result());
    other_ = two.begin_session("bob", small_task(), "sim", "", "station-02");
  }
  static std::string uri(const std::string& role) { return test::postgres_uri("t_role_script", role); }
  static inline std::string owner_;
  static inline int64_t done_ = 0, other_ = 0;
};

TEST_F(PostgresRoleScript, InstallsEveryGrantAndPolicyAndNothingElse) {
  PostgresConnection c(owner_, true);
  EXPECT_EQ(grants(c, false), expected_table_grants());
  EXPECT_EQ(grants(c, true), expected_column_grants());
  EXPECT_EQ(policies(c), expected_policies());
  for (const SqlRow& row :
       c.query("SELECT relname, relrowsecurity FROM pg_class WHERE relnamespace = 'public'::regnamespace "
               "AND relkind = 'r'",
               {}, "")
           .rows) {
    const bool secured = std::set<std::string>{"sessions",         "step_results",     "metrics",
                                               "score_components", "recording_chunks", "session_checks"}
                             .count(row.text(0)) > 0;
    EXPECT_EQ(row.integer(1) != 0, secured) << row.text(0);
  }
  // A station's rows are its own: each station policy names session_user (the login role).
  for (const SqlRow& row : c.query("SELECT policyname, coalesce(qual, '') || coalesce(with_check, '') FROM pg_policies "
                                   "WHERE tablename = 'sessions' AND policyname LIKE 'station%'",
                                   {}, "")
                               .rows)
    EXPECT_NE(row.text(1).find("SESSION_USER"), std::string::npos) << row.text(0) << ": " << row.text(1);
}

// What a station could try, as station-01 on its own finished session and on everyone's trainees
// and tasks.
TEST_F(PostgresRoleScript, EveryTamperingStatementOfAStationIsAPermissionError) {
  PostgresConnection station(uri("station-01"), false);
  const std::string id = std::to_string(done_);
  for (const std::string& sql : std::vector<std::string>{
           "UPDATE sessions SET score = 100, passed = 1 WHERE id = " + id + " AND status = 'complete'",
           "UPDATE sessions SET status = 'incomplete' WHERE id = " + id, "DELETE FROM sessions WHERE id = " + id,
           "INSERT INTO step_results VALUES (" + id + ", 9, 'forged', 'completed', 0, 1)",
           "INSERT INTO recording_chunks VALUES (" + id + ", 3, '\\x00', 0)",
           "INSERT INTO metrics VALUES (" + id + ", -1, 'forged', 1)",
           "INSERT INTO score_components VALUES (" + id + ", 9, 'forged', 1, 100)",
           "UPDATE step_results SET outcome = 'completed' WHERE session_id = " + id,
           "UPDATE metrics SET value = 0 WHERE session_id = " + id,
           "UPDATE recording_chunks SET crc = 0 WHERE session_id = " + id,
           "DELETE FROM recording_chunks WHERE session_id = " + id,
           "UPDATE trainees SET name = 'renamed-by-station-01' WHERE name = 'alice'",
           "UPDATE trainees SET name = 'renamed-by-station-01' WHERE name = 'bob'",
           "DELETE FROM trainees WHERE name = 'bob'", "UPDATE tasks SET title = 'hijacked title', source = '/evil'",
           "DELETE FROM tasks",
           "INSERT INTO session_checks(session_id, checked_at, outcome, digest, detail) VALUES (" + id +
               ", 'now', 'verified', 'x', '')",
           "INSERT INTO sessions(trainee_id, task_id, started_at, status, station) VALUES (1, 1, 'x', 'complete', "
           "'station-01')",
           "UPDATE sessions SET station = 'station-02' WHERE id = " + id}) {
    const std::string error = message_of([&] { station.script(sql, ""); });
    EXPECT_TRUE(permission_error(error)) << sql << "\n" << error;
  }
  SessionStore owner(owner_, kReadOnly);
  EXPECT_DOUBLE_EQ(owner.load(done_).info.score, a_result().score.total);
  EXPECT_EQ(owner.load(other_).info.trainee, "bob");
  EXPECT_EQ(owner.sessions().size(), 2u);
}

TEST_F(PostgresRoleScript, AStationWorksOnItsOwnSessionsAsARunDoes) {
  SessionStore station(uri("station-02"));
  ASSERT_EQ(station.sessions().size(), 1u) << "its own only";
  station.append_recording(other_, 0, "xyz");
  const int64_t more = station.begin_session("alice", small_task(), "sim", "", "station-02");  // alice exists: reused
  station.finish_session(more, a_result());
  EXPECT_TRUE(station.load(more).info.complete);
  EXPECT_EQ(station.load(more).info.trainee, "alice");
  // Its name must be its login role, and the refusal says so.
  const std::string wrong = message_of([&] { station.begin_session("bob", small_task(), "sim", "", "lab-pc-7"); });
  EXPECT_NE(wrong.find("row-level security"), std::string::npos) << wrong;
  EXPECT_NE(wrong.find("the station name \"lab-pc-7\" must be this station's login role, \"station-02\""),
            std::string::npos)
      << wrong;
  EXPECT_NE(wrong.find("--station NAME, default the host name"), std::string::npos) << wrong;
}

TEST_F(PostgresRoleScript, AnInstructorReadsAllRenamesLoggedAndChecksInItsOwnName) {
  SessionStore lee(uri("dr-lee"));
  EXPECT_GE(lee.sessions().size(), 2u);
  const TraineeRename r = lee.rename_trainee("bob", "robert");
  EXPECT_EQ(r.renamed_by, "dr-lee");
  EXPECT_EQ(lee.trainee_renames().back().new_name, "robert");
  lee.record_check({done_, CheckOutcome::kVerified, a_result().score.total, "digest", "", "", "someone-else"});
  EXPECT_EQ(lee.load(done_).check->checked_by, "dr-lee") << "the login role, whatever is said";
  PostgresConnection raw(uri("dr-lee"), false);
  for (const std::string& sql : std::vector<std::string>{
           "INSERT INTO session_checks(session_id, checked_at, checked_by, outcome, digest, detail) VALUES (" +
               std::to_string(done_) + ", 'now', 'dr-other', 'verified', 'x', '')",
           std::string("UPDATE sessions SET score = 0"), std::string("UPDATE tasks SET title = 'x'"),
           std::string("DELETE FROM trainee_renames"),
           std::string("UPDATE trainees SET id = 99 WHERE name = 'robert'")}) {
    const std::string error = message_of([&] { raw.script(sql, ""); });
    EXPECT_TRUE(permission_error(error)) << sql << "\n" << error;
  }
  // A station may not rename, nor read the log.
  SessionStore station(uri("station-01"));
  EXPECT_TRUE(permission_error(message_of([&] { station.rename_trainee("alice", "alicia"); })));
  EXPECT_TRUE(permission_error(message_of([&] { station.trainee_renames(); })));
}

TEST(PostgresRoleScriptPrerequisites, WithoutThemNothingIsChangedAndTheMissingOneIsNamed) {
  const auto applied_nothing = [](const std::string& uri) {
    PostgresConnection c(uri, true);
    EXPECT_TRUE(grants(c, false).empty());
    EXPECT_TRUE(policies(c).empty());
    if (c.query("SELECT to_regclass('sessions') IS NOT NULL", {}, "").rows[0].integer(0)) {
      EXPECT_EQ(
          c.query("SELECT relrowsecurity::int FROM pg_class WHERE relname = 'sessions'", {}, "").rows[0].integer(0), 0);
    }
  };
  // The owner the docs used to describe: no CREATEROLE.
  const std::string plain = owned_database("t_roles_plain", "plain_owner", false);
  std::string error = message_of([&] { PostgresConnection(plain, false).script(roles_sql(), "applying the roles"); });
  EXPECT_NE(error.find(
                "nothing was changed: missing the CREATEROLE attribute (role plain_owner has neither it nor SUPERUSER"),
            std::string::npos)
      << error;
  applied_nothing(plain);
  // No schema yet.
  const std::string empty = owned_database("t_roles_empty", "empty_owner", true, false);
  error = message_of([&] { PostgresConnection(empty, false).script(roles_sql(), "applying the roles"); });
  EXPECT_NE(error.find("missing the session schema"), std::string::npos) << error;
  applied_nothing(empty);
  // A role with CREATEROLE that does not own the tables.
  test::postgres_admin(
      "DO $$ BEGIN CREATE ROLE not_owner LOGIN CREATEROLE; EXCEPTION WHEN duplicate_object THEN NULL; END $$");
  error = message_of([&] {
    PostgresConnection(test::postgres_uri("t_roles_plain", "not_owner"), false)
        .script(roles_sql(), "applying the roles");
  });
  EXPECT_NE(error.find("ownership of the session tables (they belong to plain_owner, not not_owner)"),
            std::string::npos)
      << error;
  applied_nothing(plain);
}

}  // namespace
}  // namespace needle::training
