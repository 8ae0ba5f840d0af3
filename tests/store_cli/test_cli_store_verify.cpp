// needle-sim verify against a PostgreSQL server, as an instructor runs it: a session a run stored is
// verified and the check kept in the instructor's name; a score the owner role changed past the
// trigger, and a recording chunk altered (its CRC made to match, then not), are found.
#include <gtest/gtest.h>

#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>

#include "haptics/recording/crc32.hpp"
#include "rigid_run.hpp"
#include "tests/support/test_paths.hpp"
#include "tests/support/test_postgres.hpp"
#include "tests/tools/cli_process.hpp"
#include "training/sessions/session_store.hpp"

namespace needle::test {
namespace {
namespace fs = std::filesystem;

bool says(const ProcessResult& r, const std::string& text) { return r.output.find(text) != std::string::npos; }

TEST(CliStoreVerify, VerifyCatchesAScoreTheOwnerChangedAndARecordingChunkAltered) {
  const std::string uri = fresh_postgres_database("cli_verify");
  const fs::path dir = fresh_store_dir("verify");
  ASSERT_EQ(run_needle_sim(rigid_run_arguments(uri, dir)).exit_code, 0);
  const nlohmann::json score = nlohmann::json::parse(std::ifstream(dir / "out" / "score.json"));
  fs::remove(score["recording"].get<std::string>());  // an instructor's desk: the server's copy is what is verified
  const auto verify = [&](const std::string& as) {
    return run_needle_sim("verify --all --db '" + as + "' --out " + quoted(dir / "v"));
  };
  // An instructor verifies, and its check is kept under its own role.
  std::ifstream roles(source_dir() / "tools" / "postgres-roles.sql");
  test::postgres_admin({std::istreambuf_iterator<char>(roles), std::istreambuf_iterator<char>()}, "cli_verify");
  test::postgres_admin(
      "DO $$ BEGIN CREATE ROLE \"dr-verify\" LOGIN IN ROLE needle_instructor; "
      "EXCEPTION WHEN duplicate_object THEN NULL; END $$");
  const std::string instructor = postgres_uri("cli_verify", "dr-verify");
  ProcessResult r = verify(instructor);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_TRUE(says(r, "session 1: verified")) << r.output;
  {
    training::SessionStore store(uri, training::kReadOnly);
    ASSERT_TRUE(store.load(1).check);
    EXPECT_EQ(store.load(1).check->checked_by, "dr-verify");
    EXPECT_EQ(training::verification(store.sessions().at(0)), training::Verification::kVerified);
  }
  // The owner role past the trigger: the score raised.
  test::postgres_admin(
      "ALTER TABLE sessions DISABLE TRIGGER session_final; UPDATE sessions SET score = 100; "
      "ALTER TABLE sessions ENABLE TRIGGER session_final",
      "cli_verify");
  r = verify(instructor);
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_TRUE(says(r, "session 1: MISMATCH")) << r.output;
  EXPECT_TRUE(says(r, "score: stored 100, replay ")) << r.output;
  EXPECT_EQ(training::verification(training::SessionStore(uri, training::kReadOnly).sessions().at(0)),
            training::Verification::kMismatch);
  char stored[32];
  std::snprintf(stored, sizeof stored, "%.17g", score["score"].get<double>());
  test::postgres_admin(std::string("ALTER TABLE sessions DISABLE TRIGGER session_final; UPDATE sessions SET score = ") +
                           stored + "; ALTER TABLE sessions ENABLE TRIGGER session_final",
                       "cli_verify");
  ASSERT_EQ(verify(uri).exit_code, 0) << "the score put back verifies again";
  // A chunk in the middle altered, its CRC made to match: the recording's own block checksum
  // refuses it. Then altered without the CRC: the chunk's checksum does.
  training::PostgresConnection owner(uri, false);
  const int64_t middle = owner
                             .query(
                                 "SELECT byte_offset FROM recording_chunks ORDER BY byte_offset OFFSET "
                                 "(SELECT count(*) / 2 FROM recording_chunks) LIMIT 1",
                                 {}, "")
                             .rows.at(0)
                             .integer(0);
  std::string bytes =
      owner.query("SELECT bytes FROM recording_chunks WHERE byte_offset = ?", {middle}, "").rows.at(0).blob(0);
  bytes[bytes.size() / 2] ^= 0x10;
  owner.script("ALTER TABLE recording_chunks DISABLE TRIGGER session_rows_final", "");
  owner.query("UPDATE recording_chunks SET bytes = ?, crc = ? WHERE byte_offset = ?",
              {training::SqlBlob{bytes}, int64_t(haptics::crc32(bytes.data(), bytes.size())), middle}, "");
  r = verify(instructor);
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_TRUE(says(r, "session 1: unverifiable: ")) << r.output;
  EXPECT_TRUE(says(r, ": block at byte ")) << "the recording's own check\n" << r.output;
  EXPECT_TRUE(says(r, "checksum mismatch")) << r.output;
  owner.query("UPDATE recording_chunks SET crc = crc + 1 WHERE byte_offset = ?", {middle}, "");
  r = verify(instructor);
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_TRUE(
      says(r, "reading the recording of session 1: chunk at byte " + std::to_string(middle) + ": checksum mismatch"))
      << r.output;
  EXPECT_EQ(training::verification(training::SessionStore(uri, training::kReadOnly).sessions().at(0)),
            training::Verification::kUnverified);
}

}  // namespace
}  // namespace needle::test
