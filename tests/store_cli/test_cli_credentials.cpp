// needle-sim against a server that checks a password (scram-sha-256 for the role needle_password,
// tests/support/with-postgres.sh), the password given only through PGPASSFILE: it connects, over
// the socket and over TLS on 127.0.0.1 (sslmode=require, and verify-full against the test's
// self-signed certificate), and no output or error ever holds the password; a wrong or missing
// one is a clear error that does not hold it either.
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "tests/support/test_postgres.hpp"
#include "tests/tools/cli_process.hpp"
#include "training/sessions/postgres_connection.hpp"
#include "training/sessions/session_store.hpp"

namespace needle::test {
namespace {
namespace fs = std::filesystem;

const std::string kPassword = "Tr0ub4dor-scram-7";
const std::string kWrong = "wrong-Pw-4711";

// A password file for libpq (host:port:database:user:password, owner-only or libpq ignores it).
// libpq names the file in its error ("password retrieved from file ..."): `name` says which it is.
fs::path pass_file(const fs::path& dir, const std::string& name, const std::string& password) {
  const fs::path file = dir / ("pgpass_" + name);
  std::ofstream(file) << "*:*:*:needle_password:" << password << "\n";
  fs::permissions(file, fs::perms::owner_read | fs::perms::owner_write, fs::perm_options::replace);
  return file;
}

class CliCredentials : public testing::Test {
 protected:
  static void SetUpTestSuite() {
    postgres_admin("DROP DATABASE IF EXISTS cli_password WITH (FORCE)");
    postgres_admin("DROP ROLE IF EXISTS needle_password");
    postgres_admin("CREATE ROLE needle_password LOGIN PASSWORD '" + kPassword + "'");
    postgres_admin("CREATE DATABASE cli_password OWNER needle_password");
    dir_ = test_output_dir("cli_credentials");
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  // needle-sim ARGS with PGPASSFILE=`passfile`; the output checked for both passwords.
  static ProcessResult needle_sim(const fs::path& passfile, const std::string& args) {
    ProcessResult r = run_command("NEEDLE_VALIDATION=1 PGPASSFILE=" + quoted(passfile) + " " +
                                  needle_sim_exe().string() + " " + args);
    EXPECT_EQ(r.output.find(kPassword), std::string::npos) << r.output;
    EXPECT_EQ(r.output.find(kWrong), std::string::npos) << r.output;
    return r;
  }
  static std::string socket_uri() { return postgres_uri("cli_password", "needle_password"); }
  static std::string tls_uri(const std::string& sslmode) {
    return "postgresql://needle_password@127.0.0.1:" + postgres_port() + "/cli_password?sslmode=" + sslmode;
  }
  static std::string run_arguments(const std::string& uri, const std::string& name) {
    return "run --headless --size 320x240 --trainee ana --station station-pw --db '" + uri + "' --local " +
           quoted(dir_ / (name + ".db")) + " --out " + quoted(dir_ / name);
  }
  static inline fs::path dir_;
};

TEST_F(CliCredentials, TheServerReallyAsksForAScramPassword) {
  // The role's password is stored as a SCRAM verifier, and without a password file the server refuses.
  training::PostgresConnection admin(postgres_uri("postgres"), true);
  const std::string verifier =
      admin.query("SELECT rolpassword FROM pg_authid WHERE rolname = 'needle_password'", {}, "").rows.at(0).text(0);
  EXPECT_EQ(verifier.rfind("SCRAM-SHA-256$", 0), 0u);
  const ProcessResult none = needle_sim(dir_ / "no_such_passfile",
                                        "report --cohort --db '" + socket_uri() + "' --out " + quoted(dir_ / "none"));
  EXPECT_EQ(none.exit_code, 1) << none.output;
  EXPECT_NE(none.output.find("no password supplied"), std::string::npos) << none.output;
}

TEST_F(CliCredentials, APasswordFromPgpassfileConnectsAndIsNeverPrinted) {
  const fs::path right = pass_file(dir_, "right", kPassword);
  const ProcessResult run = needle_sim(right, run_arguments(socket_uri(), "socket"));
  ASSERT_EQ(run.exit_code, 0) << run.output;
  const nlohmann::json score = nlohmann::json::parse(std::ifstream(dir_ / "socket" / "score.json"));
  EXPECT_TRUE(score["stored"].get<bool>());
  EXPECT_FALSE(score["kept_for_sync"].get<bool>());
  const ProcessResult report =
      needle_sim(right, "report --cohort --db '" + socket_uri() + "' --out " + quoted(dir_ / "cohort"));
  ASSERT_EQ(report.exit_code, 0) << report.output;
  EXPECT_GE(nlohmann::json::parse(std::ifstream(dir_ / "cohort" / "cohort.json"))["sessions"].get<int>(), 1);
}

TEST_F(CliCredentials, AWrongPasswordIsAClearErrorWithoutIt) {
  const ProcessResult wrong = needle_sim(pass_file(dir_, "wrong", kWrong),
                                         "report --cohort --db '" + socket_uri() + "' --out " + quoted(dir_ / "wrong"));
  EXPECT_EQ(wrong.exit_code, 1) << wrong.output;
  EXPECT_NE(wrong.output.find("password authentication failed for user \"needle_password\""), std::string::npos)
      << wrong.output;
  EXPECT_NE(wrong.output.find("postgresql:///cli_password"), std::string::npos) << "names the server\n" << wrong.output;
  EXPECT_NE(wrong.output.find("password retrieved from file"), std::string::npos)
      << "and where the password came from\n"
      << wrong.output;
  // In the URI (user:password@), the same error, the URI shown with *** for it.
  const std::string in_uri =
      "postgresql://needle_password:" + kWrong + "@/cli_password?host=" + postgres_dir() + "&port=" + postgres_port();
  const ProcessResult uri = needle_sim(dir_ / "no_such_passfile",
                                       "report --cohort --db '" + in_uri + "' --out " + quoted(dir_ / "wrong_uri"));
  EXPECT_EQ(uri.exit_code, 1) << uri.output;
  EXPECT_NE(uri.output.find("password authentication failed"), std::string::npos) << uri.output;
  EXPECT_NE(uri.output.find("postgresql://needle_password:***@/cli_password"), std::string::npos) << uri.output;
}

TEST_F(CliCredentials, OverTlsOnly) {
  const fs::path right = pass_file(dir_, "right", kPassword);
  // A run over TCP with sslmode=require: stored, the password from the file.
  const ProcessResult run = needle_sim(right, run_arguments(tls_uri("require"), "tls"));
  ASSERT_EQ(run.exit_code, 0) << run.output;
  EXPECT_TRUE(nlohmann::json::parse(std::ifstream(dir_ / "tls" / "score.json"))["stored"].get<bool>());
  // The connection is encrypted (pg_stat_ssl of its own backend), and the certificate verifies
  // against the test's own (verify-full: signed by it and made out to 127.0.0.1).
  const std::string verified =
      tls_uri("verify-full") + "&sslrootcert=" + postgres_dir() + "/tls/server.crt&passfile=" + right.string();
  training::PostgresConnection c(verified, true);
  const training::SqlResult ssl =
      c.query("SELECT CASE WHEN ssl THEN 1 ELSE 0 END, version FROM pg_stat_ssl WHERE pid = pg_backend_pid()", {}, "");
  ASSERT_EQ(ssl.rows.size(), 1u);
  EXPECT_EQ(ssl.rows[0].integer(0), 1);
  EXPECT_EQ(ssl.rows[0].text(1).rfind("TLS", 0), 0u) << ssl.rows[0].text(1);
  // Without TLS the server has no way in over TCP.
  const ProcessResult plain =
      needle_sim(right, "report --cohort --db '" + tls_uri("disable") + "' --out " + quoted(dir_ / "plain"));
  EXPECT_EQ(plain.exit_code, 1) << plain.output;
  EXPECT_NE(plain.output.find("no encryption"), std::string::npos) << plain.output;
}

}  // namespace
}  // namespace needle::test
