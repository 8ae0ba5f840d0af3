// `needle-sim bench tick` and `bench precision`: tables and the JSON keys of issue 3.
#include <gtest/gtest.h>

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

TEST(CliHapticsBench, TickReportsMedianP99AndNoAllocations) {
  const auto rows = rows_of("bench tick --ticks 2000", test::output_dir().string() + "/bench_tick.json");
  ASSERT_EQ(rows.size(), 3u);
  for (const auto& row : rows) {
    EXPECT_GT(row["median_us"].get<double>(), 0.0);
    EXPECT_GE(row["p99_us"].get<double>(), row["median_us"].get<double>());
    EXPECT_EQ(row["allocations_per_tick"].get<double>(), 0.0);
  }
}

TEST(CliHapticsBench, PrecisionRowsCarryTheContractKeys) {
  const auto rows = rows_of("bench precision --horizon 0.008", test::output_dir().string() + "/bench_precision.json");
  ASSERT_EQ(rows.size(), 14u);  // 2 integrators × 7 steps
  for (const auto& row : rows)
    for (const char* key : {"integrator", "dt_s", "time_per_step_us", "error", "drift_mps", "fitted_order", "theoretical_order"})
      EXPECT_TRUE(row.contains(key)) << key;
  EXPECT_EQ(rows.front()["dt_s"].get<double>(), 0.004);
  EXPECT_EQ(rows.back()["dt_s"].get<double>(), 6.25e-5);
}

TEST(CliHapticsBench, BadArgumentsAreUsageErrors) {
  EXPECT_EQ(test::run_needle_sim_split("bench tick --ticks 0").exit_code, 2);
  EXPECT_EQ(test::run_needle_sim_split("bench precision --horizon 0.001").exit_code, 2);
  EXPECT_EQ(test::run_needle_sim_split("bench stability --sustained 1").exit_code, 2);
}

}  // namespace
}  // namespace needle::test
