// `needle-sim model`: the JSON contract and the exit codes for bad input.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "cli_haptics_run.hpp"
#include "tests/support/test_paths.hpp"

namespace needle::test {
namespace {

const std::string kMaster = test::source_dir().string() + "/assets/robots/master_omni.urdf";

TEST(CliHapticsModel, PrintsTheIssueKeys) {
  const auto r = test::run_needle_sim("model --robot " + kMaster + " --q 0,0,0,0,0 --dq 0.1,0,0,0,0");
  ASSERT_EQ(r.exit_code, 0);
  const auto j = nlohmann::json::parse(r.out);
  for (const char* key : {"pose", "J", "H", "Cdq", "g", "gravity", "tau_id"}) EXPECT_TRUE(j.contains(key)) << key;
  // Stretched arm: tip at l1 + l2 + tool on the x axis.
  EXPECT_NEAR(j["pose"]["p"][0].get<double>(), 0.13335 * 2 + 0.05, 1e-12);
}

TEST(CliHapticsModel, WrongJointCountIsAUsageError) {
  EXPECT_EQ(test::run_needle_sim("model --robot " + kMaster + " --q 0,0,0").exit_code, 2);
}

TEST(CliHapticsModel, MissingFileIsAnError) {
  EXPECT_EQ(test::run_needle_sim("model --robot /nonexistent.urdf --q 0").exit_code, 1);
}

}  // namespace
}  // namespace needle::test
