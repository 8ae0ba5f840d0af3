// What needle-sim writes and keeps, as a user meets it: a full disk is exit 1 naming the file and
// the reason, never "wrote" over an empty file; a damaged database is refused before a run starts;
// report and review read a database they cannot write.
#include <gtest/gtest.h>

#include <chrono>
#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>

#include "cli_process.hpp"
#include "tests/support/full_disk.hpp"
#include "tests/support/process_folder.hpp"
#include "training/sessions/session_store.hpp"

namespace needle::test {
namespace {

namespace fs = std::filesystem;

bool says(const ProcessResult& r, const std::string& text) { return r.output.find(text) != std::string::npos; }

std::string run_args(const fs::path& out, const fs::path& db) {
  return "run --headless --size 160x120 --task " + quoted(source_dir() / "assets/tasks/rigid_sphere.json") + " --out " +
         quoted(out) + " --db " + quoted(db);
}

TEST(CliWrites, RenderIntoAFullDeviceIsAnError) {
  const ProcessResult r =
      run_needle_sim("render --gltf " + quoted(source_dir() / "assets/needle.gltf") + " --size 64x48 --out /dev/full");
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_TRUE(says(r, "/dev/full: cannot write: No space left on device")) << r.output;
  EXPECT_FALSE(says(r, "wrote")) << r.output;
}

// An output folder that cannot be made (under a plain file, in /proc) is exit 1 naming the folder.
TEST(CliWrites, AnOutputFolderThatCannotBeMadeIsAnErrorNamingIt) {
  const fs::path dir = process_folder(test_output_dir("cli_writes") / "no_folder");
  { std::ofstream(dir / "plain") << "x"; }
  for (const fs::path& out : {dir / "plain" / "out", fs::path("/proc/needle-sim-out")}) {
    const ProcessResult r =
        run_needle_sim("simulate --scenario " + quoted(source_dir() / "assets/scenarios/holonomic_sphere.json") +
                       " --out " + quoted(out));
    EXPECT_EQ(r.exit_code, 1) << r.output;
    EXPECT_TRUE(says(r, out.string() + ": cannot create the folder: ")) << r.output;
    EXPECT_FALSE(says(r, "filesystem error")) << r.output;
  }
  const ProcessResult r = run_needle_sim(run_args(dir / "plain" / "run", dir / "sessions.db"));
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_TRUE(says(r, (dir / "plain" / "run").string() + ": cannot create the folder: Not a directory")) << r.output;
}

TEST(CliWrites, ARunOntoAFullDiskFailsNamingTheFileAndLeavesNoEmptyFile) {
  const fs::path dir = process_folder(test_output_dir("cli_writes") / "full");
  FullTmpfs disk(dir / "out", 256 * 1024);
  if (!disk.mounted()) GTEST_SKIP() << disk.why_not();
  disk.leave_free(8 * 1024);  // room for the scenario, not for every picture: the disk fills mid-run
  const ProcessResult r = run_needle_sim(run_args(disk.dir(), dir / "sessions.db"));
  EXPECT_TRUE(fs::is_regular_file(disk.dir() / "scenario.json")) << r.output;
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_TRUE(says(r, disk.dir().string() + "/")) << r.output;
  EXPECT_TRUE(says(r, ": cannot write: No space left on device")) << r.output;
  EXPECT_FALSE(says(r, "wrote")) << r.output;
  for (const auto& e : fs::directory_iterator(disk.dir()))
    if (e.path().filename() != "filler") EXPECT_GT(fs::file_size(e.path()), 0u) << e.path();
}

TEST(CliWrites, AScoreThatCannotBeWrittenIsAnErrorAndTheSessionIsStillStored) {
  const fs::path dir = process_folder(test_output_dir("cli_writes") / "score");
  // A folder where score.json goes (with a file in it, so the run cannot clear it away).
  fs::create_directories(dir / "out" / "score.json");
  std::ofstream(dir / "out" / "score.json" / "keep") << "x";
  const ProcessResult r = run_needle_sim(run_args(dir / "out", dir / "sessions.db"));
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_TRUE(says(r, (dir / "out" / "score.json").string() + ": cannot write: it is a folder")) << r.output;
  EXPECT_FALSE(says(r, "wrote " + (dir / "out" / "score.json").string())) << r.output;
  training::SessionStore store(dir / "sessions.db", training::kReadOnly);
  ASSERT_EQ(store.sessions().size(), 1u);
  EXPECT_TRUE(store.sessions()[0].complete);
}

std::vector<char> bytes_of(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

TEST(CliWrites, ADamagedDatabaseIsRefusedBeforeTheRunAndByTheReport) {
  const fs::path dir = process_folder(test_output_dir("cli_writes") / "damaged");
  const fs::path db = dir / "sessions.db";
  ASSERT_EQ(run_needle_sim(run_args(dir / "first", db)).exit_code, 0);
  std::vector<char> good = bytes_of(db);
  std::vector<char> bad = good;
  std::fill(bad.end() - 4096, bad.end(), 0);  // the last page zeroed
  std::ofstream(db, std::ios::binary).write(bad.data(), std::streamsize(bad.size()));

  const auto t0 = std::chrono::steady_clock::now();
  ProcessResult r = run_needle_sim(run_args(dir / "second", db));
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_TRUE(says(r, db.string() + ": the session database is damaged (PRAGMA quick_check: ")) << r.output;
  EXPECT_FALSE(says(r, "simulated")) << "refused before the run\n" << r.output;
  EXPECT_LT(seconds, 3.0) << r.output;
  EXPECT_EQ(bytes_of(db), bad) << "left as it was";
  EXPECT_FALSE(fs::exists(dir / "second" / "score.json"));

  // A database cut short: the report is an error, not a session with its score breakdown missing.
  std::ofstream(db, std::ios::binary).write(good.data(), std::streamsize(good.size() / 2));
  r = run_needle_sim("report --session 1 --db " + quoted(db) + " --out " + quoted(dir / "report"));
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_TRUE(says(r, db.string() + ": the session database is damaged")) << r.output;
  EXPECT_FALSE(fs::exists(dir / "report" / "session_1.json"));
}

TEST(CliWrites, ReportReadsADatabaseInAFolderItCannotWrite) {
  const fs::path dir = process_folder(test_output_dir("cli_writes") / "read_only");
  ASSERT_EQ(run_needle_sim(run_args(dir / "run", dir / "sessions.db")).exit_code, 0);
  const ReadOnlyFolder folder(dir / "ro");
  fs::copy_file(dir / "sessions.db", folder.dir() / "sessions.db");
  ASSERT_EQ(folder.make_read_only(), "");
  const ProcessResult r = run_needle_sim("report --session 1 --db " + quoted(folder.dir() / "sessions.db") + " --out " +
                                         quoted(dir / "report"));
  EXPECT_EQ(r.exit_code, 0) << r.output;  // the recording is found by its absolute path
  EXPECT_TRUE(fs::is_regular_file(dir / "report" / "session_1.json")) << r.output;
  EXPECT_TRUE(fs::is_regular_file(dir / "report" / "plot_force.png")) << r.output;
}

}  // namespace
}  // namespace needle::test
