// `needle-sim model`: the JSON contract and the exit codes for bad input.
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "cli_process.hpp"
#include "tests/support/test_paths.hpp"

namespace needle::test {
namespace {

const std::string kMaster = test::source_dir().string() + "/assets/robots/master_omni.urdf";

TEST(CliHapticsModel, PrintsTheIssueKeys) {
  const auto r = test::run_needle_sim_split("model --robot " + kMaster + " --q 0,0,0,0,0 --dq 0.1,0,0,0,0");
  ASSERT_EQ(r.exit_code, 0);
  const auto j = nlohmann::json::parse(r.out);
  for (const char* key : {"pose", "J", "H", "Cdq", "g", "gravity", "tau_id"}) EXPECT_TRUE(j.contains(key)) << key;
  // Stretched arm: tip at l1 + l2 + tool on the x axis.
  EXPECT_NEAR(j["pose"]["p"][0].get<double>(), 0.13335 * 2 + 0.05, 1e-12);
}

TEST(CliHapticsModel, WrongJointCountIsAUsageError) {
  EXPECT_EQ(test::run_needle_sim_split("model --robot " + kMaster + " --q 0,0,0").exit_code, 2);
}

TEST(CliHapticsModel, ResultsThatAreNotFiniteAreAnErrorNotNulls) {
  const auto r = test::run_needle_sim_split("model --robot " + kMaster + " --q 0,0,0,0,0 --dq 1e308,1e308,0,0,0");
  EXPECT_EQ(r.exit_code, 1) << r.out;
  EXPECT_EQ(r.out.find("null"), std::string::npos) << r.out;
  EXPECT_NE(r.err.find("is not finite at this state"), std::string::npos) << r.err;
}

TEST(CliHapticsModel, AUrdfThatUrdfdomRejectsIsOneLine) {
  const std::string file = test::output_dir().string() + "/nan_mass.urdf";
  std::ofstream(file) << R"(<robot name="r"><link name="base"/><link name="arm"><inertial><mass value="nan"/>
    <inertia ixx="1" ixy="0" ixz="0" iyy="1" iyz="0" izz="1"/></inertial></link><joint name="j1" type="revolute">
    <parent link="base"/><child link="arm"/><axis xyz="0 0 1"/><limit lower="-1" upper="1" effort="1" velocity="1"/></joint></robot>)";
  const auto r = test::run_needle_sim_split("model --robot " + file + " --q 0");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(r.err, "needle-sim model: error: " + file +
                       ": not a valid URDF document: Inertial: mass [nan] is not a float; "
                       "Could not parse inertial element for Link [arm]\n");
}

TEST(CliHapticsModel, MissingFileIsAnError) {
  EXPECT_EQ(test::run_needle_sim_split("model --robot /nonexistent.urdf --q 0").exit_code, 1);
}

}  // namespace
}  // namespace needle::test
