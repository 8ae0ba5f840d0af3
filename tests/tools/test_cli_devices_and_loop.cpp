// `needle-sim devices` lists every backend with what it needs; `needle-sim bench loop --json`
// writes the row keys other tools read, haptic and bare rows side by side, with and without the
// rendering load.
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "cli_process.hpp"

namespace needle::test {
namespace {

TEST(CliDevices, ListsEveryBackendAndWhatItNeeds) {
  ProcessResult r = run_needle_sim("devices");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  for (const char* backend : {"falcon", "mouse", "replay:FILE", "sim:SCENARIO"}) {
    EXPECT_NE(r.output.find(backend), std::string::npos) << backend << "\n" << r.output;
  }
  EXPECT_NE(r.output.find("needs:"), std::string::npos) << r.output;
}

// With a display, the gamepads GLFW reports (the virtual display has none).
TEST(CliDevices, WithADisplayListsTheGamepadsPresent) {
  ProcessResult r = run_on_virtual_display(needle_sim_exe().string() + " devices");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("gamepad[:N]  none connected"), std::string::npos) << r.output;
}

TEST(CliBenchLoop, JsonRowsCarryTheContractKeys) {
  auto json_path = test_output_dir("cli_bench_loop") / "loop.json";
  ProcessResult r =
      run_needle_sim("bench loop --rates 500 --seconds 0.3 --device mouse --render-load --json " + quoted(json_path));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  nlohmann::json rows = nlohmann::json::parse(std::ifstream(json_path));
  ASSERT_EQ(rows.size(), 4u);  // haptic and bare, alone and under the rendering load
  int haptic = 0, loaded = 0;
  for (const auto& row : rows) {
    for (const char* key :
         {"loop", "rate_hz", "render_load", "period_err_p50_us", "period_err_p99_us", "period_err_p999_us",
          "period_err_max_us", "overruns", "compute_p50_us", "compute_p99_us"}) {
      ASSERT_TRUE(row.contains(key)) << key << " in " << row.dump();
    }
    EXPECT_EQ(row["rate_hz"], 500);
    haptic += row["loop"] == "haptic";
    loaded += row["render_load"].get<bool>();
    EXPECT_LE(row["period_err_p50_us"].get<double>(), row["period_err_max_us"].get<double>());
  }
  EXPECT_EQ(haptic, 2);
  EXPECT_EQ(loaded, 2);
}

}  // namespace
}  // namespace needle::test
