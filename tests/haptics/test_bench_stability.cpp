// Stress cases end bounded or in a latched fault that names its cause, never silently.
#include <gtest/gtest.h>

#include "haptics/sim/stress_cases.hpp"
#include "sim_fixtures.hpp"

namespace needle::haptics {
namespace {

TEST(BenchStability, PrintedVirtualLawEndsInANamedFaultInClosedLoop) {
  Scenario s = test::scenario("holonomic_sphere");
  s.gains.virtual_feedback = VirtualFeedback::AsPrinted;
  const SimResult r = run_closed_loop(s, false);
  ASSERT_EQ(r.summary.faults.size(), 1u);
  EXPECT_LT(r.simulated_s, 2.0);  // caught at once, not after a long silent drift
  const std::string& f = r.summary.faults.front();
  EXPECT_TRUE(f.rfind("non_finite_state", 0) == 0 || f.rfind("energy_bound_exceeded", 0) == 0 ||
              f.rfind("tracking_diverged", 0) == 0)
      << f;
}

TEST(BenchStability, PushAtTwiceTheForceLimitStaysBoundedAndSaturates) {
  const Scenario& h = test::scenario("holonomic_sphere");
  const Scenario s = pressing(h, 2 * h.device.force_limit_N, 10.0);
  double deepest = 0;
  const SimResult r =
      run_closed_loop(s, false, [&](const TickRecord& t) { deepest = std::max(deepest, -t.lambda_v[0]); });
  EXPECT_TRUE(r.summary.faults.empty());
  // The device cannot resist more than its limit, so the hand pushes the tool harder than that.
  EXPECT_GT(deepest, h.device.force_limit_N);
  EXPECT_LT(r.summary.max_penetration_m, 0.02);
}

TEST(BenchStability, CasesCoverTheIssueSweeps) {
  const auto cases = stress_cases(test::scenario("holonomic_sphere"), test::scenario("nonholonomic_needle"), 3600.0);
  int gains = 0, periods = 0, singular = 0, push = 0, sustained = 0, stiffness = 0;
  for (const StressCase& c : cases) {
    gains += c.name.rfind("gains", 0) == 0;
    periods += c.name.rfind("period", 0) == 0;
    singular += c.name == "singular pose";
    push += c.name == "operator push";
    sustained += c.name == "sustained contact" && c.scenario.duration_s >= 3600.0;
    stiffness += c.name.rfind("penalty stiffness", 0) == 0;
  }
  EXPECT_EQ(gains, 14);
  EXPECT_EQ(periods, 8);
  EXPECT_EQ(singular, 2);
  EXPECT_EQ(push, 1);
  EXPECT_EQ(sustained, 1);
  EXPECT_EQ(stiffness, 5);
  EXPECT_DOUBLE_EQ(passivity_stiffness_bound(test::scenario("holonomic_sphere")), 2 * 6.45 / 0.002);
}

// The layered sweeps: puncture force, friction and stiffness each x0.1 to x10 on every layer
// that is not bone, the period x1 to x8, a push onto bone at twice the device's limit.
TEST(BenchStability, LayeredCasesCoverTheIssueSweeps) {
  const Scenario& block = test::scenario("tissue_block_layers");
  const auto cases = layered_stress_cases(block);
  int puncture = 0, friction = 0, stiffness = 0, periods = 0, bone = 0;
  for (const StressCase& c : cases) {
    puncture += c.name.rfind("puncture force", 0) == 0;
    friction += c.name.rfind("friction", 0) == 0;
    stiffness += c.name.rfind("stiffness", 0) == 0;
    periods += c.name.rfind("period", 0) == 0;
    bone += c.name.rfind("push onto bone", 0) == 0;
  }
  EXPECT_EQ(puncture, 5);
  EXPECT_EQ(friction, 5);
  EXPECT_EQ(stiffness, 5);
  EXPECT_EQ(periods, 4);
  EXPECT_EQ(bone, 1);
  // The x10 friction row scales the muscle's numbers and leaves bone rigid.
  const StressCase& x10 = cases[3 * 4 + 1];
  ASSERT_EQ(x10.value, "10");
  const TissueModel& scaled = x10.scenario.scene.tissue;
  for (int i = 0; i < scaled.layer_count(); ++i) {
    const LayerMechanics &m = scaled.layer(i).mechanics, &m0 = block.scene.tissue.layer(i).mechanics;
    EXPECT_EQ(m.rigid, m0.rigid);
    EXPECT_DOUBLE_EQ(m.friction_N_per_m, 10 * m0.friction_N_per_m);
    EXPECT_DOUBLE_EQ(m.static_friction_N_per_m, 10 * m0.static_friction_N_per_m);
    EXPECT_DOUBLE_EQ(m.puncture_force_N, m0.puncture_force_N);
  }
  // The liver has no bone: no push row.
  for (const StressCase& c : layered_stress_cases(test::scenario("liver_biopsy")))
    EXPECT_NE(c.name.rfind("push onto bone", 0), 0u);
}

// The push onto the block's bone plate at twice the device's limit: the needle stops on the bone,
// the run ends bounded or in a named fault, and the device saturates (the hand pushes harder than it can resist).
TEST(BenchStability, PushOntoBoneAtTwiceTheLimitEndsBoundedOrNamed) {
  const Scenario& block = test::scenario("tissue_block_layers");
  const Scenario s = pushing_onto_bone(block, 2 * block.device.force_limit_N);
  double deepest_z = 1.0;
  const SimResult r =
      run_closed_loop(s, false, [&](const TickRecord& t) { deepest_z = std::min(deepest_z, t.x_v.z()); });
  if (!r.summary.faults.empty()) {
    const std::string& f = r.summary.faults.front();
    EXPECT_TRUE(f.rfind("non_finite_state", 0) == 0 || f.rfind("energy_bound_exceeded", 0) == 0 ||
                f.rfind("tracking_diverged", 0) == 0)
        << f;
  } else {
    EXPECT_DOUBLE_EQ(r.simulated_s, s.duration_s);
  }
  // The bone plate's top face is at z = 0.030 m (world): the tip stops on it within the penalty's give.
  EXPECT_GT(deepest_z, 0.030 - 0.005);
}

}  // namespace
}  // namespace needle::haptics
