// `needle-sim bench deform --json`: the row keys other tools read, and rows that add up.
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "cli_process.hpp"

namespace needle::test {
namespace {

TEST(CliBenchDeform, JsonRowsCarryTheContractKeysAndAddUp) {
  auto json_path = test_output_dir("cli_bench_deform") / "deform.json";
  ProcessResult r = run_needle_sim("bench deform --spheres 20,60 --frames 4 --json " + quoted(json_path));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_EQ(r.output.find("Vulkan validation"), std::string::npos) << r.output;
  nlohmann::json rows = nlohmann::json::parse(std::ifstream(json_path));
  ASSERT_EQ(rows.size(), 2u);
  for (const auto& row : rows) {
    for (const char* key : {"vertices", "processed", "skipped", "gpu_ms", "cpu_ms", "max_abs_error_m"}) {
      ASSERT_TRUE(row.contains(key)) << key;
    }
    EXPECT_EQ(row["processed"].get<long>() + row["skipped"].get<long>(), row["vertices"].get<long>());
    EXPECT_LT(row["max_abs_error_m"].get<double>(), 1e-6);  // the GPU pass agrees with the CPU reference
  }
  EXPECT_EQ(rows[0]["vertices"], 21 * 21);
  EXPECT_EQ(rows[1]["vertices"], 61 * 61);
}

TEST(CliBenchDeform, BadArgumentsAreUsageErrors) {
  EXPECT_EQ(run_needle_sim("bench deform --spheres 2").exit_code, 2);
  EXPECT_EQ(run_needle_sim("bench deform --frames 1").exit_code, 2);
}

}  // namespace
}  // namespace needle::test
