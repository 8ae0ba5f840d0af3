// `needle-sim bench tick` and `bench precision`: tables and their documented JSON keys.
#include <gtest/gtest.h>

#include <chrono>
#include <fstream>
#include <nlohmann/json.hpp>

#include "cli_process.hpp"
#include "tests/support/test_paths.hpp"

namespace needle::test {
namespace {

nlohmann::json rows_of(const std::string& command, const std::string& json_path) {
  const auto r = test::run_needle_sim_split(command + " --json " + json_path);
  EXPECT_EQ(r.exit_code, 0) << command;
  std::ifstream in(json_path);
  return nlohmann::json::parse(in);
}

TEST(CliHapticsBench, TickReportsMedianAndP99) {
  const auto rows = rows_of("bench tick --ticks 2000", test::output_dir().string() + "/bench_tick.json");
  ASSERT_EQ(rows.size(), 4u);  // 1, 2, 4 sub-steps, then the patient
  EXPECT_EQ(rows[0]["scenario"], "nonholonomic_needle");
  EXPECT_EQ(rows[3]["scenario"], "epidural_patient");
  for (const auto& row : rows) {
    EXPECT_GT(row["median_us"].get<double>(), 0.0);
    EXPECT_GE(row["p99_us"].get<double>(), row["median_us"].get<double>());
  }
}

TEST(CliHapticsBench, PrecisionRowsCarryTheContractKeys) {
  const auto rows = rows_of("bench precision --horizon 0.008", test::output_dir().string() + "/bench_precision.json");
  ASSERT_EQ(rows.size(), 14u);  // 2 integrators × 7 steps
  for (const auto& row : rows)
    for (const char* key :
         {"integrator", "dt_s", "time_per_step_us", "error", "drift_mps", "fitted_order", "theoretical_order"})
      EXPECT_TRUE(row.contains(key)) << key;
  EXPECT_EQ(rows.front()["dt_s"].get<double>(), 0.004);
  EXPECT_EQ(rows.back()["dt_s"].get<double>(), 6.25e-5);
}

TEST(CliHapticsBench, BadArgumentsAreUsageErrors) {
  EXPECT_EQ(test::run_needle_sim_split("bench tick --ticks 0").exit_code, 2);
  const auto huge = test::run_needle_sim_split("bench tick --ticks 9223372036854775807");
  EXPECT_EQ(huge.exit_code, 2);
  EXPECT_NE(huge.err.find("--ticks: expected a whole number from 1 to 100000000, got '9223372036854775807'"),
            std::string::npos)
      << huge.err;
  EXPECT_EQ(test::run_needle_sim_split("bench precision --horizon 0.001").exit_code, 2);
  EXPECT_EQ(test::run_needle_sim_split("bench stability --sustained 1").exit_code, 2);
}

// `bench` is a group: alone, with --help or with a name it does not have, it lists its benches.
TEST(CliHapticsBench, TheBenchGroupListsItsBenches) {
  const auto help = test::run_needle_sim_split("bench --help");
  EXPECT_EQ(help.exit_code, 0);
  for (const char* bench :
       {"bench deform", "bench loop", "bench precision", "bench render", "bench stability", "bench tick"})
    EXPECT_NE(help.out.find(std::string("  needle-sim ") + bench), std::string::npos) << bench << "\n" << help.out;
  const auto bare = test::run_needle_sim_split("bench");
  EXPECT_EQ(bare.exit_code, 2);
  EXPECT_EQ(bare.err, help.out);
  const auto unknown = test::run_needle_sim_split("bench frobnicate");
  EXPECT_EQ(unknown.exit_code, 2);
  EXPECT_EQ(unknown.err, "needle-sim: unknown command 'bench frobnicate'\n" + help.out);
}

// --json into a folder that does not exist is refused before the bench runs, not after.
TEST(CliHapticsBench, AJsonFileInAMissingFolderIsRefusedBeforeTheRun) {
  const auto t0 = std::chrono::steady_clock::now();
  const auto r = test::run_needle_sim_split("bench tick --json /nonexistent/folder/tick.json");
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(), 2.0) << "the bench ran first";
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("--json: folder /nonexistent/folder does not exist"), std::string::npos) << r.err;
  EXPECT_EQ(r.out, "");
}

}  // namespace
}  // namespace needle::test
