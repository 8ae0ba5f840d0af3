// Thesis section 4.4 reproduced without a device: free motion, insertion, pivot, insertion.
#include <gtest/gtest.h>

#include <cmath>

#include "sim_fixtures.hpp"

namespace needle::haptics {
namespace {

const SimResult& run() { return test::scenario_run("nonholonomic_needle"); }

const TickRecord& at(double t) {
  const auto& ticks = run().ticks;
  const auto index = static_cast<size_t>(std::lround(t / test::scenario("nonholonomic_needle").period_s)) - 1;
  return ticks.at(index);
}

double degrees(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  return std::acos(std::clamp(a.normalized().dot(b.normalized()), -1.0, 1.0)) * 180 / M_PI;
}

TEST(SimNonholonomic, RunsToTheEndWithoutFault) {
  EXPECT_TRUE(run().summary.faults.empty());
  EXPECT_LT(run().summary.energy_error_J, 1e-3);
}

// Entry at about 3.8 s (tool law; 3.7 s under the thesis's law, which then flickers in and out until
// 5.2 s: test_sim_feel.cpp).
TEST(SimNonholonomic, NeedleEntersTheTissueAroundFourSecondsAndStaysIn) {
  double first = -1;
  for (const TickRecord& r : run().ticks)
    if (r.mode == ContactMode::Nonholonomic) {
      first = r.t;
      break;
    }
  EXPECT_GT(first, 3.0);
  EXPECT_LT(first, 4.5);
  for (const TickRecord& r : run().ticks) {
    if (r.t > 5.5) {
      ASSERT_EQ(r.mode, ContactMode::Nonholonomic) << "left the tissue at t = " << r.t;
    }
  }
}

TEST(SimNonholonomic, TipPathStaysAlongTheNeedleAxis) {
  EXPECT_LT(run().summary.max_axis_deviation_m, 1e-3);
  EXPECT_LT(run().summary.max_lateral_speed_mps, 0.02);
  // Straight insertion 4-10 s: displacement parallel to the needle, within 3 degrees under the
  // thesis's law. Under the tool law the wrist no longer hangs in its gravity equilibrium: the
  // scripted hand holds the stylus's direction only through its 5 cm grip, the wrist roll drifts
  // (0.45 -> 1.64 rad from 5 to 10 s), the needle turns and the tip follows it, 3.55 degrees off the
  // direction it had at 5 s (docs/CONTROLLER.md, "The tool").
  for (ControlLaw law : {ControlLaw::Thesis, ControlLaw::Tool}) {
    const auto& ticks = test::scenario_run("nonholonomic_needle", law).ticks;
    const auto tick = [&](double t) -> const TickRecord& {
      return ticks.at(static_cast<size_t>(std::lround(t / test::scenario("nonholonomic_needle").period_s)) - 1);
    };
    const Eigen::Vector3d d = tick(10.0).x_v - tick(5.0).x_v;
    EXPECT_GT(d.norm(), 0.015) << control_law_name(law);
    EXPECT_LT(degrees(d, tick(5.0).needle_v), law == ControlLaw::Thesis ? 3.0 : 4.0) << control_law_name(law);
  }
}

TEST(SimNonholonomic, PivotTurnsTheNeedleAbout45DegreesWithoutMovingTheTip) {
  EXPECT_NEAR(degrees(at(10.0).needle_v, at(30.0).needle_v), 45.0, 5.0);
  EXPECT_LT((at(30.0).x_v - at(10.5).x_v).norm(), 0.002);
}

TEST(SimNonholonomic, SecondInsertionFollowsTheNewDirection) {
  const Eigen::Vector3d d = at(40.0).x_v - at(31.0).x_v;
  EXPECT_GT(d.norm(), 0.01);
  EXPECT_LT(degrees(d, at(31.0).needle_v), 3.0);
  EXPECT_NEAR(degrees(at(40.0).needle_v, Eigen::Vector3d(0, 0, -1)), 0.0, 5.0);  // vertical
}

TEST(SimNonholonomic, PositionErrorLargerInFreeMotionAndForcesTrack) {
  const SimSummary& s = run().summary;
  EXPECT_GT(s.position_rms_free_m, 2.0 * s.position_rms_contact_m);
  EXPECT_LT(s.force_max_N, 1.0);
  // The operator feels lateral forces: λ_m is not zero in tissue.
  double felt = 0;
  for (const TickRecord& r : run().ticks) felt = std::max(felt, std::hypot(r.lambda_m[0], r.lambda_m[1]));
  EXPECT_GT(felt, 0.05);
}

}  // namespace
}  // namespace needle::haptics
