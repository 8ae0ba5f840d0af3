// `needle-sim simulate`: its documented files and keys, the layered tissue's among them.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "cli_process.hpp"
#include "tests/support/test_paths.hpp"

namespace needle::test {
namespace {

TEST(CliHapticsSimulate, WritesTicksCsvAndSummaryWithTheIssueKeys) {
  const std::string out = test::output_dir().string() + "/simulate_holonomic";
  std::filesystem::remove_all(out);
  const auto r = test::run_needle_sim_split("simulate --scenario " + test::source_dir().string() +
                                            "/assets/scenarios/holonomic_sphere.json --out " + out);
  ASSERT_EQ(r.exit_code, 0);
  std::ifstream summary_file(out + "/summary.json");
  ASSERT_TRUE(summary_file);
  const auto summary = nlohmann::json::parse(summary_file);
  for (const char* key :
       {"position_rms_free_m", "position_max_free_m", "position_rms_contact_m", "position_max_contact_m", "force_rms_N",
        "force_max_N", "max_penetration_m", "max_lateral_speed_mps", "max_axis_deviation_m", "energy_error_J", "faults",
        "punctures", "tissue_work_J", "hand_work_J", "hand_work_min_J", "world_dissipated_min_J", "saturated_s",
        "passivity_damped_s"})
    EXPECT_TRUE(summary.contains(key)) << key;
  EXPECT_EQ(summary.size(), 18u) << "exactly the issues' keys";
  EXPECT_TRUE(summary["punctures"].empty());  // a rigid sphere: no tissue
  EXPECT_EQ(summary["tissue_work_J"], 0.0);
  EXPECT_TRUE(summary["faults"].empty());
  std::ifstream csv(out + "/ticks.csv");
  std::string header, line;
  std::getline(csv, header);
  EXPECT_EQ(header.rfind("t,q_m1,", 0), 0u) << header;
  for (const char* column : {"x_m_x", "x_v_z", "F_h_x", "F_v_y", "lambda_v1", "lambda_m2", "phi", "psi1", "energy",
                             "mode,axial_force_N,layer,hand_work_J,world_stored_J"})
    EXPECT_NE(header.find(column), std::string::npos) << column;
  long rows = 0;
  while (std::getline(csv, line)) ++rows;
  EXPECT_EQ(rows, 22000);  // 44 s at 2 ms
}

TEST(CliHapticsSimulate, MissingScenarioIsAnError) {
  EXPECT_EQ(test::run_needle_sim_split("simulate --scenario /nonexistent.json --out /tmp/x").exit_code, 1);
  EXPECT_EQ(test::run_needle_sim_split("simulate --out /tmp/x").exit_code, 2);
}

}  // namespace
}  // namespace needle::test
