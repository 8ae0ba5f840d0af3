// needle-sim's command line as CLI11 declares it: every command answers --help, and a value
// outside its flag's range, an empty name or file, an MSAA count that is not one, a date that is
// no day is a usage error (exit 2) in one line naming the flag and what was expected, before
// anything runs.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <sstream>

#include "cli_process.hpp"
#include "tests/support/test_paths.hpp"

namespace needle::test {
namespace {

size_t line_count(const std::string& s) { return size_t(std::count(s.begin(), s.end(), '\n')); }

// The commands `needle-sim --help` lists: its lines "  needle-sim NAME  summary".
std::vector<std::pair<std::string, std::string>> listed_commands() {
  const ProcessResult help = run_needle_sim("--help");
  EXPECT_EQ(help.exit_code, 0) << help.output;
  std::vector<std::pair<std::string, std::string>> commands;
  std::istringstream lines(help.output);
  for (std::string line; std::getline(lines, line);) {
    if (line.rfind("  needle-sim ", 0) != 0) continue;
    const size_t gap = line.find("  ", 13);
    commands.emplace_back(line.substr(13, gap - 13), line.substr(line.find_first_not_of(' ', gap)));
  }
  return commands;
}

TEST(CliUsage, EveryCommandListedAnswersHelpWithItsSummaryAndUsage) {
  const auto commands = listed_commands();
  std::vector<std::string> names;
  for (const auto& [name, summary] : commands) names.push_back(name);
  for (const char* expected : {"run", "review", "report", "sync", "render", "model", "simulate", "devices",
                               "bench render", "bench tick", "bench stability", "bench frame"})
    EXPECT_NE(std::find(names.begin(), names.end(), expected), names.end()) << expected;
  for (const auto& [name, summary] : commands) {
    const ProcessResult r = run_needle_sim(name + " --help");
    EXPECT_EQ(r.exit_code, 0) << name << "\n" << r.output;
    EXPECT_EQ(r.output.rfind(summary + "\nusage: needle-sim " + name, 0), 0u) << name << "\n" << r.output;
  }
}

// What a usage error must be: exit 2, one line on stderr naming the command, the flag and what
// it expected, nothing on stdout, and soon (nothing ran).
void expect_usage_error(const std::string& arguments, const std::string& says) {
  const auto t0 = std::chrono::steady_clock::now();
  const SplitResult r = run_needle_sim_split(arguments);
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(), 10.0) << arguments;
  EXPECT_EQ(r.exit_code, 2) << arguments << "\n" << r.err;
  EXPECT_EQ(line_count(r.err), 1u) << arguments << "\n" << r.err;
  EXPECT_NE(r.err.find(says), std::string::npos) << arguments << "\n" << r.err;
  EXPECT_EQ(r.out, "") << arguments;
}

TEST(CliUsage, CountsAndDurationsPastTheirRangeAreRefusedNamingFlagAndRange) {
  expect_usage_error("bench stability --sustained 1e300",
                     "--sustained: expected a number from 10 to 36000, got '1e300'");
  expect_usage_error("bench tick --settle 1e12", "--settle: expected a number in (0, 1800], got '1e12'");
  expect_usage_error("bench frame --warmup 1e12", "--warmup: expected a whole number from 0 to 10000, got '1e12'");
  expect_usage_error("bench frame --frames 1e9", "--frames: expected a whole number from 10 to 100000, got '1e9'");
  expect_usage_error("bench loop --seconds 1e9", "--seconds: expected a number in (0, 3600], got '1e9'");
  expect_usage_error("bench render --frames 0", "--frames: expected a whole number from 1 to 100000, got '0'");
  expect_usage_error("bench ultrasound --frames 1e6", "--frames: expected a whole number from 2 to 100000, got '1e6'");
  expect_usage_error("bench precision --horizon 1e6", "--horizon: expected a number in (0.004, 10], got '1e6'");
  expect_usage_error("bench store --sessions 1e9", "--sessions: expected a whole number from 1 to 10000, got '1e9'");
  expect_usage_error("run --frames 1e300", "--frames: expected a whole number from 1 to 1000000000, got '1e300'");
  expect_usage_error("run --rate nan", "--rate: expected a number from 250 to 10000, got 'nan'");
  expect_usage_error("report --session 1 --out x --at 1e9", "--at: expected a number from 0 to 1800, got '1e9'");
  expect_usage_error("bench deform --spheres 100,5000",
                     "--spheres: expected a whole number from 3 to 2000, got '5000'");
  expect_usage_error(
      "bench loop --rates 1000,1000,1000,1000,1000,1000,1000,1000,1000,1000,1000,1000,1000,1000,1000,1000,1000",
      "--rates: expected at most 16 items, got 17");
  // The whole drive of bench insertion, in, held and out, is bounded too.
  expect_usage_error("bench insertion --scenario " + quoted(source_dir() / "assets/scenarios/lumbar_epidural.json") +
                         " --from 0.33,0,0.075 --dir 0,0,-1 --depth 1 --speed 1e-4",
                     "--depth, --speed, --hold: the drive would last 20000");
}

TEST(CliUsage, MsaaIsOneTwoFourOrEight) {
  expect_usage_error("run --msaa 1e10", "--msaa: expected 1, 2, 4 or 8, got '1e10'");
  expect_usage_error("bench render --msaa 4.5", "--msaa: expected 1, 2, 4 or 8, got '4.5'");
  expect_usage_error("bench render --msaa 1,3", "--msaa: expected 1, 2, 4 or 8, got '3'");
  expect_usage_error("render --scene a.json --out x.png --msaa 16", "--msaa: expected 1, 2, 4 or 8, got '16'");
}

TEST(CliUsage, EmptyNamesFilesAndLocationsAreRefused) {
  expect_usage_error("run --db ''", "needle-sim run: --db: expected FILE|URI, got ''");
  expect_usage_error("run --operator ''", "--operator: expected good|sloppy|FILE, got ''");
  expect_usage_error("run --trainee ''", "--trainee: expected NAME, got ''");
  expect_usage_error("run --station ''", "--station: expected NAME, got ''");
  expect_usage_error("run --device replay:", "--device: device 'replay:': expected a recording file after replay:");
  expect_usage_error("run --device ''",
                     "--device: expected sim|mouse|keyboard|gamepad[:N]|falcon[:N]|replay:FILE, got ''");
  expect_usage_error("report --cohort --out x --trainee ''", "--trainee: expected NAME, got ''");
  expect_usage_error("report --cohort --out x --station ''", "--station: expected NAME, got ''");
  expect_usage_error("review --db ''", "--db: expected FILE|URI, got ''");
  expect_usage_error("sync --db ''", "--db: expected URI, got ''");
  expect_usage_error("--db ''", "needle-sim: --db: expected FILE|URI, got ''");
  expect_usage_error("--station ''", "needle-sim: --station: expected NAME, got ''");
}

TEST(CliUsage, DatesAreDaysOfTheCalendar) {
  const std::string db = quoted(output_dir() / "no_such.db");
  expect_usage_error("report --cohort --out x --db " + db + " --since 2026-13-45",
                     "--since: expected a date YYYY-MM-DD, got '2026-13-45'");
  expect_usage_error("report --cohort --out x --db " + db + " --until 2026-02-30",
                     "--until: expected a date YYYY-MM-DD, got '2026-02-30'");
}

TEST(CliUsage, UnknownCommandsAndOptionsAreUsageErrors) {
  expect_usage_error("frobnicate", "needle-sim: unknown command 'frobnicate'");
  expect_usage_error("run --frobnicate", "needle-sim run: The following argument was not expected: --frobnicate");
  expect_usage_error("render --scene a.json --gltf b.gltf --out x.png", "needle-sim render: --scene excludes --gltf");
  expect_usage_error("--db x.db run", "--db, --station and --debug before a command are the start screen's");
  expect_usage_error("--debug run", "--db, --station and --debug before a command are the start screen's");
}

}  // namespace
}  // namespace needle::test
