// The pieces of the closed loop: hand trajectory, hand impedance, force sensor, device plant,
// scenario loading errors.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <iterator>
#include <regex>

#include "haptics/model/kinematics.hpp"
#include "haptics/sim/closed_loop.hpp"
#include "haptics/sim/force_sensor.hpp"
#include "haptics/sim/master_plant.hpp"
#include "haptics/sim/scenario.hpp"
#include "robot_fixtures.hpp"

namespace needle::haptics {
namespace {

using Eigen::Vector3d;

TEST(SimComponents, HandTrajectoryBlendsWithMinimumJerkAndConsistentRates) {
  const HandTrajectory tr({{0.0, Vector3d(0, 0, 0), Vector3d(1, 0, 0)}, {2.0, Vector3d(0.1, 0, 0), Vector3d(0, 1, 0)}});
  EXPECT_TRUE(tr.at(-1.0).position.isZero());
  EXPECT_TRUE(tr.at(1.0).position.isApprox(Vector3d(0.05, 0, 0)));             // symmetric profile
  EXPECT_TRUE(tr.at(1.0).direction.isApprox(Vector3d(1, 1, 0).normalized()));  // halfway on the arc
  EXPECT_TRUE(tr.at(5.0).position.isApprox(Vector3d(0.1, 0, 0)));
  EXPECT_TRUE(tr.at(5.0).velocity.isZero());
  const double t = 0.7, h = 1e-6;
  EXPECT_TRUE(tr.at(t).velocity.isApprox((tr.at(t + h).position - tr.at(t - h).position) / (2 * h), 1e-6));
  const Vector3d d_dot = (tr.at(t + h).direction - tr.at(t - h).direction) / (2 * h);
  EXPECT_TRUE(d_dot.isApprox(tr.at(t).omega.cross(tr.at(t).direction), 1e-6));
  EXPECT_THROW(HandTrajectory({{1.0, Vector3d::Zero(), Vector3d::UnitX()}, {1.0, Vector3d::Zero(), Vector3d::UnitX()}}),
               std::invalid_argument);
}

// Through many waypoints the target at a waypoint's own time is that waypoint, and between two
// it is their minimum-jerk blend, whichever waypoint the search starts from.
TEST(SimComponents, HandTrajectoryFindsItsSegmentAmongManyWaypoints) {
  std::vector<HandWaypoint> waypoints;
  for (int k = 0; k < 1001; ++k)
    waypoints.push_back({0.01 * k, Vector3d(0.001 * k * k, -0.002 * k, 0.0), Vector3d::UnitX()});
  const HandTrajectory tr(waypoints);
  for (int k : {0, 1, 499, 500, 999, 1000})
    EXPECT_TRUE(tr.at(waypoints[size_t(k)].t).position.isApprox(waypoints[size_t(k)].position)) << k;
  for (int k : {0, 437, 999}) {
    const HandWaypoint &a = waypoints[size_t(k)], &b = waypoints[size_t(k) + 1];
    const double u = 0.5;  // halfway: the minimum-jerk profile's s(1/2) = 1/2
    EXPECT_TRUE(tr.at(a.t + u * (b.t - a.t)).position.isApprox(0.5 * (a.position + b.position))) << k;
  }
  EXPECT_TRUE(tr.at(-1.0).position.isApprox(waypoints.front().position));
  EXPECT_TRUE(tr.at(99.0).position.isApprox(waypoints.back().position));
}

TEST(SimComponents, HandImpedancePullsTowardTheTargetAndTurnsTheStylus) {
  const HandImpedance hand;
  HandTarget target{Vector3d(0.01, 0, 0), Vector3d::Zero(), Vector3d(0, 1, 0), Vector3d::Zero()};
  const Wrench w =
      hand_impedance_wrench(hand, target, Eigen::Isometry3d::Identity(), Eigen::Matrix<double, 6, 1>::Zero());
  EXPECT_TRUE(w.head<3>().isApprox(Vector3d(1.35, 0, 0)));                         // 135 N/m × 1 cm
  EXPECT_TRUE(w.tail<3>().isApprox(Vector3d(0, 0, hand.rotational_stiffness())));  // x₅ → y about +z
}

TEST(SimComponents, ForceSensorHasItsBiasNoiseAndBandwidth) {
  ForceSensorParams p;
  p.bandwidth_Hz = 50.0;
  ForceSensor sensor(p);
  sensor.reset(Wrench::Zero());
  Wrench step = Wrench::Zero();
  step[0] = 1.0;
  const double dt = 1e-4;
  double at_tau = 0;
  const int tau_samples = static_cast<int>(std::round(1.0 / (2 * M_PI * 50.0) / dt));
  for (int i = 1; i <= tau_samples; ++i) at_tau = sensor.read(step, dt)[0];
  EXPECT_NEAR(at_tau - p.bias[0], 1.0 - std::exp(-1.0), 0.02);  // 63 % after one time constant
  double sum = 0, sum_sq = 0;
  const int n = 20000;
  for (int i = 0; i < n; ++i) {
    const double e = sensor.read(step, dt)[1] - p.bias[1];
    sum += e;
    sum_sq += e * e;
  }
  EXPECT_NEAR(sum / n, 0.0, 4 * p.force_noise_N / std::sqrt(n));
  EXPECT_NEAR(std::sqrt(sum_sq / n), p.force_noise_N, 0.05 * p.force_noise_N);
}

TEST(SimComponents, DeviceActuatesThreeJointsAndSaturatesAtItsForceLimit) {
  const RobotModel m = test::master_robot();
  HandImpedance no_hand;
  no_hand.mass_kg = no_hand.stiffness_N_per_m = no_hand.damping_Ns_per_m = 0.0;
  MasterPlant plant(m, DeviceParams{}, no_hand, Integrator::SemiImplicitEuler, 8);
  const VecN q0 = (VecN(5) << 0.0, 1.0, -1.6, 0.0, 0.5).finished();
  plant.reset(q0, VecN::Zero(5));
  const HandTrajectory still({{0.0, Vector3d::Zero(), Vector3d::UnitX()}});
  plant.advance(VecN::Constant(5, 5.0), still, 0.0, 0.002);
  EXPECT_EQ(plant.applied_torque()[3], 0.0);
  EXPECT_EQ(plant.applied_torque()[4], 0.0);
  EXPECT_TRUE(plant.saturated());
  RobotData d(m);
  update_kinematics(m, d, q0, VecN::Zero(5));
  const Eigen::Matrix3d jt = d.J.topLeftCorner(3, 3).transpose();
  EXPECT_NEAR(jt.inverse().operator*(Vector3d(plant.applied_torque().head<3>())).norm(), 3.3, 1e-9);
}

TEST(SimComponents, DeviceEnergyBalancesTheWorkDoneOnIt) {
  const RobotModel m = test::master_robot();
  MasterPlant plant(m, DeviceParams{}, HandImpedance{}, Integrator::Rk4, 8);
  const VecN q0 = (VecN(5) << 0.0, 1.0, -1.6, 0.0, 0.5).finished();
  plant.reset(q0, VecN::Zero(5));
  const HandTrajectory moving(
      {{0.0, Vector3d(0.2, 0.0, 0.0), Vector3d::UnitX()}, {1.0, Vector3d(0.2, 0.05, 0.0), Vector3d::UnitY()}});
  const double e0 = plant.energy();
  for (int k = 0; k < 500; ++k) plant.advance(VecN::Constant(5, 0.01), moving, k * 0.002, 0.002);
  EXPECT_GT(std::abs(plant.external_work()), 1e-3);  // the hand did real work
  EXPECT_NEAR(plant.energy() - e0, plant.external_work(), 1e-5);
}

TEST(SimComponents, ScenarioErrorsNameTheFileAndTheKey) {
  const std::string path = ::testing::TempDir() + "/bad_scenario.json";
  std::ofstream(path) << R"({"name": "x", "master_urdf": ")" << test::asset("assets/robots/master_omni.urdf")
                      << R"(", "virtual_urdf": ")" << test::asset("assets/robots/virtual_needle_robot.urdf")
                      << R"(", "robot_base_in_world_m": [0, 0], "period_s": 0.002})";
  try {
    load_scenario(path);
    FAIL();
  } catch (const ScenarioError& e) {
    EXPECT_EQ(std::string(e.what()), path + ": /robot_base_in_world_m: expected an array of 3 numbers");
  }
  EXPECT_THROW(load_scenario("/nonexistent.json"), ScenarioError);
  std::string text;
  {
    std::ifstream in(test::asset("assets/scenarios/holonomic_sphere.json"));
    text.assign(std::istreambuf_iterator<char>(in), {});
  }
  const std::string fraction = ::testing::TempDir() + "/fraction_substeps.json";
  text = std::regex_replace(text, std::regex("\\.\\./robots/"), test::asset("assets/robots/"));
  std::ofstream(fraction) << std::regex_replace(text, std::regex("\"master_substeps\": 8"), "\"master_substeps\": 0.5");
  try {
    load_scenario(fraction);
    FAIL();
  } catch (const ScenarioError& e) {
    EXPECT_NE(std::string(e.what()).find(": /master_substeps: expected a whole number"), std::string::npos) << e.what();
  }
}

// The scenario reader is the project's strict reader: unknown keys and impossible values are
// errors with the file and the JSON pointer, not silently accepted.
TEST(SimComponents, ScenarioRejectsUnknownKeysAndImpossibleHands) {
  std::string text;
  {
    std::ifstream in(test::asset("assets/scenarios/holonomic_sphere.json"));
    text.assign(std::istreambuf_iterator<char>(in), {});
  }
  text = std::regex_replace(text, std::regex("\\.\\./robots/"), test::asset("assets/robots/"));
  auto error_of = [&](const std::string& from, const std::string& to) {
    const std::string path = ::testing::TempDir() + "/edited_scenario.json";
    std::ofstream(path) << std::regex_replace(text, std::regex(from), to);
    try {
      load_scenario(path);
    } catch (const ScenarioError& e) {
      return std::string(e.what()).substr(path.size());
    }
    return std::string("no error");
  };
  EXPECT_EQ(error_of("\"mass_kg\": 0.554", "\"mass_kg\": 0"), ": /hand/mass_kg: must be in (0, 10] kg, got 0");
  EXPECT_EQ(error_of("\"mass_kg\": 0.554", "\"mass_kg\": -1"), ": /hand/mass_kg: must be in (0, 10] kg, got -1");
  EXPECT_EQ(error_of("\"mass_kg\"", "\"mass_kgs\"").substr(0, 32), ": /hand/mass_kgs: unknown key (a");
  EXPECT_EQ(error_of("\"period_s\"", "\"period\"").substr(0, 23), ": /period: unknown key ");
  EXPECT_EQ(error_of("\"preset\": \"thesis_holonomic\"", "\"preset\": \"fast\""),
            ": /gains/preset: expected \"thesis_holonomic\" or \"thesis_nonholonomic\", got \"fast\"");
}

// A state that goes non-finite (here a hand stiffness of 1e300 N/m, set past the reader's range)
// is a latched fault that ends the run before the tick enters the summary: summary.json holds
// no NaN (nlohmann writes one as null).
TEST(SimComponents, ANonFiniteStateIsALatchedFaultAndTheSummaryHoldsNoNaN) {
  Scenario s = load_scenario(test::asset("assets/scenarios/holonomic_sphere.json"));
  s.hand.stiffness_N_per_m = 1e300;
  const SimResult r = run_closed_loop(s, true);
  ASSERT_EQ(r.summary.faults.size(), 1u);
  EXPECT_EQ(r.summary.faults[0].rfind("non_finite_state at t=", 0), 0u) << r.summary.faults[0];
  EXPECT_LT(r.simulated_s, s.duration_s);
  const std::string summary = r.summary.to_json().dump();
  EXPECT_EQ(summary.find("null"), std::string::npos) << summary;
  for (const TickRecord& tick : r.ticks) ASSERT_TRUE(std::isfinite(tick.energy) && tick.q_m.allFinite()) << tick.t;
}

TEST(SimComponents, ThesisScenariosLoadInTheBaseFrame) {
  const Scenario s = load_scenario(test::asset("assets/scenarios/holonomic_sphere.json"));
  // The sphere at (0.4, 0, 0) in the world is at (0.4, 0, 0) − base in the robots' frame.
  EXPECT_NEAR(s.scene.rigid.evaluate(Vector3d(0.4, 0, 0) - s.base_in_world).phi, -0.1, 1e-12);
  EXPECT_TRUE(s.scene.tissue.empty());
  EXPECT_DOUBLE_EQ(s.gains.master.Kf, 10.05);
}

}  // namespace
}  // namespace needle::haptics
