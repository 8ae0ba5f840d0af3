// The passivity observer and its controller (haptics/control/passivity_control.hpp): the energy account
// against sums done here by hand, the damper's closed form and its bound, and in closed loop the
// stress rows whose world gave the hand energy without it.
#include <gtest/gtest.h>

#include "haptics/control/passivity_control.hpp"
#include "haptics/sim/stress_cases.hpp"
#include "sim_fixtures.hpp"

namespace needle::haptics {
namespace {

VecN vec(std::initializer_list<double> v) {
  VecN out(static_cast<Eigen::Index>(v.size()));
  Eigen::Index i = 0;
  for (double x : v) out[i++] = x;
  return out;
}

TEST(PassivityObserver, AbsorbedIsMinusTheHeldTorqueTimesTheDisplacementAndStoredIsSubtracted) {
  PassivityObserver obs;
  observe_passivity(vec({0.0, 0.0}), 5.0, obs);  // U(0) = 5 J
  EXPECT_EQ(obs.absorbed_J, 0.0);
  EXPECT_EQ(obs.dissipated_J, 0.0);
  passivity_applied(vec({2.0, -1.0}), obs);
  observe_passivity(vec({0.1, 0.3}), 5.0, obs);  // the device moved against part of the torque
  const double a1 = -(2.0 * 0.1 + -1.0 * 0.3);   // +0.1 J taken from the device
  EXPECT_DOUBLE_EQ(obs.absorbed_J, a1);
  EXPECT_DOUBLE_EQ(obs.dissipated_J, a1);
  passivity_applied(vec({1.0, 1.0}), obs);
  observe_passivity(vec({0.3, 0.4}), 5.25, obs);  // the torque did 0.3 J on the device; the world holds 0.25 J more
  const double a2 = a1 - (1.0 * 0.2 + 1.0 * 0.1);
  EXPECT_DOUBLE_EQ(obs.absorbed_J, a2);
  EXPECT_DOUBLE_EQ(obs.dissipated_J, a2 - 0.25);
}

TEST(PassivityControl, OffWhileTheWorldHasDissipatedAndWithholdsAndDampsWhileItOwesEnergy) {
  const PassivityGains gains;
  MatN H(2, 2);
  H << 0.02, 0.005, 0.005, 0.01;
  const VecN dq = vec({0.5, -0.2});
  const double T = 0.002;
  const VecN command = vec({0.3, 0.1}), conservative = vec({0.05, -0.02});
  PassivityObserver obs;
  obs.dissipated_J = 1e-6;
  VecN tau = command;
  passivity_control(gains, H, dq, conservative, T, obs, tau);
  EXPECT_EQ(obs.damping_per_s, 0.0);
  EXPECT_EQ(obs.share_withheld, 0.0);
  EXPECT_EQ(tau, command);

  // A small deficit: half the active part withheld (γ = −D / D_full), and β = −D / (T q̇ᵀHq̇), so the
  // damper's work over a tick at this velocity, β q̇ᵀHq̇ T, is −D.
  const double qHq = dq.dot(H * dq);
  obs.dissipated_J = -0.5 * gains.full_at_J;
  passivity_control(gains, H, dq, conservative, T, obs, tau);
  EXPECT_DOUBLE_EQ(obs.share_withheld, 0.5);
  EXPECT_NEAR(obs.damping_per_s, 0.5 * gains.full_at_J / (T * qHq), 1e-9);
  EXPECT_NEAR(obs.damping_per_s * qHq * T, -obs.dissipated_J, 1e-18);
  const VecN expected = conservative + 0.5 * (command - conservative) - obs.damping_per_s * (H * dq);
  EXPECT_NEAR((tau - expected).norm(), 0.0, 1e-15);

  // A large one: the whole active part withheld, the damper held at β_max = max_damping_per_tick / T,
  // which brings the velocity at most to rest.
  obs.dissipated_J = -1.0;
  tau = command;
  passivity_control(gains, H, dq, conservative, T, obs, tau);
  EXPECT_EQ(obs.share_withheld, 1.0);
  EXPECT_DOUBLE_EQ(obs.damping_per_s, gains.max_damping_per_tick / T);
  EXPECT_NEAR((tau - (conservative - (1.0 / T) * (H * dq))).norm(), 0.0, 1e-12);
  // At rest nothing is damped, the active part still withheld.
  tau = command;
  passivity_control(gains, H, vec({0.0, 0.0}), conservative, T, obs, tau);
  EXPECT_EQ(obs.damping_per_s, 0.0);
  EXPECT_EQ(tau, conservative);
  // Off by setting: nothing, whatever the deficit.
  PassivityGains off;
  off.max_damping_per_tick = 0.0;
  tau = command;
  passivity_control(off, H, dq, conservative, T, obs, tau);
  EXPECT_EQ(obs.damping_per_s, 0.0);
  EXPECT_EQ(tau, command);
}

TEST(PassivityControl, TheVirtualRobotsDamperAddsToItsImplicitDampingWhileTheWorldOwesEnergy) {
  const PassivityGains gains;
  MatN H(2, 2);
  H << 0.04, 0.01, 0.01, 0.03;
  const VecN dq = vec({0.2, 0.1});
  const double T = 0.002;
  PassivityObserver obs;
  obs.dissipated_J = -1e-7;
  VecN B = vec({0.5, 0.5});
  passivity_virtual_damping(gains, H, dq, T, obs, B);
  const double diag = 0.04 * 0.2 * 0.2 + 0.03 * 0.1 * 0.1;
  EXPECT_NEAR(obs.virtual_damping_per_s, 1e-7 / (T * diag), 1e-12);
  EXPECT_NEAR(B[0], 0.5 + obs.virtual_damping_per_s * 0.04, 1e-15);
  EXPECT_NEAR(B[1], 0.5 + obs.virtual_damping_per_s * 0.03, 1e-15);
  obs.dissipated_J = 0.0;
  B = vec({0.5, 0.5});
  passivity_virtual_damping(gains, H, dq, T, obs, B);
  EXPECT_EQ(B, vec({0.5, 0.5}));
}

// The least energy the world dissipated (the bench's own account, haptics/sim/hand_port.hpp) with the
// damper and without it, for one stress row.
std::pair<double, double> dissipated_with_and_without(const Scenario& row) {
  Scenario off = row;
  off.gains.passivity.max_damping_per_tick = 0.0;
  return {run_closed_loop(row, false).summary.world_dissipated_min_J, run_closed_loop(off, false).summary.world_dissipated_min_J};
}

const StressCase& row(const std::vector<StressCase>& cases, const std::string& name, const std::string& value) {
  for (const StressCase& c : cases)
    if (c.name == name && c.value == value) return c;
  throw std::invalid_argument("no stress row " + name + " " + value);
}

// The three rows of `bench stability` where the world gave the hand the most energy without the
// damper (docs/BENCHMARKS.md): with it each dissipates, to within 1 mJ.
TEST(PassivityClosedLoop, TheWorstStressRowsDissipateWithTheDamperAndNotWithout) {
  const auto thesis = stress_cases(test::scenario("holonomic_sphere"), test::scenario("nonholonomic_needle"), 10.0);
  const auto block = layered_stress_cases(test::scenario("tissue_block_layers"));
  const auto lumbar = layered_stress_cases(test::scenario("lumbar_epidural"));
  for (const StressCase* c : {&row(thesis, "period x (nonholonomic_needle)", "8"),
                              &row(block, "puncture force x (tissue_block_layers)", "10"),
                              &row(lumbar, "period x (lumbar_epidural)", "8")}) {
    const auto [with, without] = dissipated_with_and_without(c->scenario);
    EXPECT_LT(without, -1e-3) << c->name << " " << c->value << ": the row should be one the damper is needed for";
    EXPECT_GE(with, -1e-3) << c->name << " " << c->value;
  }
}

}  // namespace
}  // namespace needle::haptics
