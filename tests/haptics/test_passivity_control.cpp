// The passivity observer and its controller (haptics/control/passivity_control.hpp): the energy account
// against sums done here by hand, the damper's closed form and its bound, and in closed loop the
// stress rows whose world gave the hand energy without it.
#include <gtest/gtest.h>

#include <limits>

#include "haptics/control/passivity_control.hpp"
#include "haptics/model/dynamics.hpp"
#include "haptics/model/kinematics.hpp"
#include "haptics/sim/master_plant.hpp"
#include "haptics/sim/stress_cases.hpp"
#include "sim_fixtures.hpp"
#include "tests/support/allocation_count.hpp"

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

// A kinematic master's limit: every joint driven, no force too large.
DeviceLimit no_limit(int n) {
  DeviceLimit limit;
  limit.force_per_torque.setZero(3, n);
  limit.force_limit_N = std::numeric_limits<double>::infinity();
  limit.actuated_joints = n;
  return limit;
}

TEST(PassivityObserver, ThePredictionIsTheDissipationIfTheDeviceKeptItsVelocity) {
  PassivityObserver obs;
  observe_passivity(vec({0.0, 0.0}), 2.0, obs);
  obs.dissipated_J = 0.004;
  const double T = 0.002;
  // τ·q̇ T = (0.5·1 + 1·(−2)) · 0.002 = −0.003 J done by the device on the world; U rises by 0.001 J.
  EXPECT_NEAR(predicted_dissipation(vec({0.5, 1.0}), vec({1.0, -2.0}), T, 2.001, obs), 0.004 + 0.003 - 0.001, 1e-15);
}

TEST(PassivityControl, OffUntilTheTickWouldLeaveADebtThenWithholdsAndDamps) {
  const PassivityGains gains;
  const DeviceLimit limit = no_limit(2);
  MatN H(2, 2);
  H << 0.02, 0.005, 0.005, 0.01;
  const VecN dq = vec({0.5, -0.2});
  const double T = 0.002;
  const VecN command = vec({0.3, 0.1}), conservative = vec({0.05, -0.02});
  PassivityObserver obs;
  // The first tick's remainder (a fraction of a microjoule) is no debt.
  for (double predicted : {1e-6, 0.0, -0.5 * gains.owed_from_J}) {
    obs.predicted_J = predicted;
    VecN tau = command;
    passivity_control(gains, limit, H, dq, conservative, T, obs, tau);
    EXPECT_EQ(obs.damping_per_s, 0.0);
    EXPECT_EQ(obs.share_withheld, 0.0);
    EXPECT_EQ(tau, command);
  }

  // A small deficit: half the active part withheld (γ = −D⁺ / D_full), what it would have done over the
  // tick undone, and the damper sized for the rest, so that its work over a tick at this velocity,
  // β q̇ᵀHq̇ T, is −(D⁺ + γ T τ_a·q̇).
  const double qHq = dq.dot(H * dq);
  const double active_work = T * (command - conservative).dot(dq);
  obs.predicted_J = -0.5 * gains.full_at_J;
  VecN tau = command;
  passivity_control(gains, limit, H, dq, conservative, T, obs, tau);
  EXPECT_DOUBLE_EQ(obs.share_withheld, 0.5);
  const double left = -0.5 * gains.full_at_J + 0.5 * active_work;
  ASSERT_LT(left, 0.0);
  EXPECT_NEAR(obs.damping_per_s * qHq * T, -left, 1e-18);
  const VecN expected = conservative + 0.5 * (command - conservative) - obs.damping_per_s * (H * dq);
  EXPECT_NEAR((tau - expected).norm(), 0.0, 1e-15);

  // A large one: the whole active part withheld, the damper held at β_max = max_damping_per_tick / T,
  // which brings the velocity at most to rest.
  obs.predicted_J = -1.0;
  tau = command;
  passivity_control(gains, limit, H, dq, conservative, T, obs, tau);
  EXPECT_EQ(obs.share_withheld, 1.0);
  EXPECT_DOUBLE_EQ(obs.damping_per_s, gains.max_damping_per_tick / T);
  EXPECT_NEAR((tau - (conservative - (1.0 / T) * (H * dq))).norm(), 0.0, 1e-12);
  // At rest nothing is damped, the active part still withheld.
  tau = command;
  passivity_control(gains, limit, H, vec({0.0, 0.0}), conservative, T, obs, tau);
  EXPECT_EQ(obs.damping_per_s, 0.0);
  EXPECT_EQ(tau, conservative);
  // Off by setting: nothing, whatever the deficit.
  PassivityGains off;
  off.max_damping_per_tick = 0.0;
  tau = command;
  passivity_control(off, limit, H, dq, conservative, T, obs, tau);
  EXPECT_EQ(obs.damping_per_s, 0.0);
  EXPECT_EQ(tau, command);
}

// On a device with motors on some joints only, the damper acts through those, with their block of H,
// and no further than the force limit lets it: the rest of the debt is carried to the next tick.
TEST(PassivityControl, TheDamperActsThroughTheMotorsAndWithinTheirLimit) {
  const Scenario& s = test::scenario("nonholonomic_needle");
  DeviceParams weak = s.device;
  weak.force_limit_N = 0.5;  // so that the damper meets it
  const DeviceLimit limit = device_limit(s.master, weak);
  RobotData d(s.master);
  const VecN dq = vec({0.4, -0.3, 0.2, 1.0, -1.0});
  update_kinematics(s.master, d, s.q0, dq);
  update_dynamics(s.master, d);
  const VecN conservative = vec({0.0, 0.02, 0.01, 0.0, 0.0});
  VecN within = conservative;
  ASSERT_EQ(limit_to_device(limit, within), 1.0);
  const double T = 0.002;
  PassivityGains gains;
  gains.full_at_J = 1e9;  // no withholding: the damper alone
  PassivityObserver obs;
  obs.predicted_J = -1e-5;
  VecN tau = conservative;
  passivity_control(gains, limit, d.H, dq, conservative, T, obs, tau);
  const Eigen::Vector3d h = d.H.topLeftCorner(3, 3) * dq.head(3);
  EXPECT_NEAR(obs.damping_per_s * T * dq.head(3).dot(h), 1e-5, 1e-15);
  EXPECT_NEAR((tau.head(3) - (conservative.head(3) - obs.damping_per_s * h)).norm(), 0.0, 1e-15);
  EXPECT_EQ(tau.tail(2), conservative.tail(2));  // no motor on the wrist
  // A debt too large for the limit: the damper stops at it.
  obs.predicted_J = -1.0;
  tau = conservative;
  passivity_control(gains, limit, d.H, dq, conservative, T, obs, tau);
  EXPECT_LT(obs.damping_per_s, gains.max_damping_per_tick / T);
  VecN limited = tau;
  EXPECT_NEAR(limit_to_device(limit, limited), 1.0, 1e-9);
  VecN further = tau - 0.01 * obs.damping_per_s * (VecN(5) << h, 0.0, 0.0).finished();
  EXPECT_LT(limit_to_device(limit, further), 1.0);
}

TEST(PassivityControl, TheVirtualRobotsDamperAddsToItsImplicitDampingWhileTheWorldOwesEnergy) {
  const PassivityGains gains;
  MatN H(2, 2);
  H << 0.04, 0.01, 0.01, 0.03;
  const VecN dq = vec({0.2, 0.1});
  const double T = 0.002;
  PassivityObserver obs;
  obs.dissipated_J = -1e-5;
  VecN B = vec({0.5, 0.5});
  passivity_virtual_damping(gains, H, dq, T, obs, B);
  const double diag = 0.04 * 0.2 * 0.2 + 0.03 * 0.1 * 0.1;
  EXPECT_NEAR(obs.virtual_damping_per_s, 1e-5 / (T * diag), 1e-10);
  EXPECT_NEAR(B[0], 0.5 + obs.virtual_damping_per_s * 0.04, 1e-15);
  EXPECT_NEAR(B[1], 0.5 + obs.virtual_damping_per_s * 0.03, 1e-15);
  for (double not_owed : {0.0, -0.5 * gains.owed_from_J}) {
    obs.dissipated_J = not_owed;
    B = vec({0.5, 0.5});
    passivity_virtual_damping(gains, H, dq, T, obs, B);
    EXPECT_EQ(B, vec({0.5, 0.5}));
  }
}

// The least energy the world dissipated (the bench's own account, haptics/sim/hand_port.hpp) with the
// damper and without it, for one stress row.
std::pair<double, double> dissipated_with_and_without(const Scenario& row) {
  Scenario off = row;
  off.gains.passivity.max_damping_per_tick = 0.0;
  return {run_closed_loop(row, false).summary.world_dissipated_min_J,
          run_closed_loop(off, false).summary.world_dissipated_min_J};
}

const StressCase& row(const std::vector<StressCase>& cases, const std::string& name, const std::string& value) {
  for (const StressCase& c : cases)
    if (c.name == name && c.value == value) return c;
  throw std::invalid_argument("no stress row " + name + " " + value);
}

// The controller on the simulated device with the scenario's scripted hand, a tick at a time, so that
// a test can watch the controller's tick: sense(), then the tick, then drive() with its output.
struct ClosedLoop {
  const Scenario& sc;
  Teleoperation tele;
  MasterPlant plant;
  TickInput in;
  long k = 0;
  explicit ClosedLoop(const Scenario& s)
      : sc(s),
        tele(s.master, s.virt, s.scene, s.gains, s.period_s, s.virtual_substeps, s.device),
        plant(s.master, s.device, s.hand, s.master_integrator, s.master_substeps) {
    tele.reset(s.q0, VecN::Zero(s.master.dof()));
    plant.reset(s.q0, VecN::Zero(s.master.dof()));
  }
  bool running() const { return k < std::lround(sc.duration_s / sc.period_s); }
  const TickInput& sense() {
    in.q_m = plant.q();
    in.dq_m = plant.dq();
    in.wrench_h = plant.hand_wrench();
    return in;
  }
  void drive(const TickOutput& out) {
    plant.advance(out.tau_m, sc.trajectory, k * sc.period_s, sc.period_s);
    ++k;
  }
};

// The controller's U⁺ is U plus T times its rate along the master's motion: that rate is the derivative of
// Teleoperation::stored_energy along q̇ (central differences), here in the epidural with the needle in
// tissue, the lateral and axial springs both on.
TEST(PassivityClosedLoop, TheStoredEnergysRateIsItsDerivativeAlongTheMastersMotion) {
  const Scenario& sc = test::scenario("epidural");
  ASSERT_GT(sc.gains.axial_stiffness_N_per_m, 0.0);
  ClosedLoop loop(sc);
  const Teleoperation& tele = loop.tele;
  const MasterPlant& plant = loop.plant;
  int in_tissue = 0;
  while (loop.running() && in_tissue < 500) {
    loop.drive(loop.tele.step(loop.sense()));
    in_tissue += tele.blend().tissue == 1.0 && tele.blend().axial == 1.0;
  }
  ASSERT_EQ(in_tissue, 500) << "the script should put the needle in the tissue";
  RobotData d(sc.master);
  update_kinematics(sc.master, d, plant.q(), plant.dq());
  update_dynamics(sc.master, d);
  const double rate = tele.stored_energy_rate(d);
  const double h = 1e-6;
  RobotData ahead(sc.master), behind(sc.master);
  update_frames(sc.master, ahead, plant.q() + h * plant.dq(), plant.dq());
  update_frames(sc.master, behind, plant.q() - h * plant.dq(), plant.dq());
  const double difference = (tele.stored_energy(ahead) - tele.stored_energy(behind)) / (2 * h);
  EXPECT_GT(std::abs(rate), 1e-4) << "a still master would test nothing";
  EXPECT_NEAR(rate, difference, 1e-6 * std::abs(difference) + 1e-9);
}

// The rows of `bench stability` where the world gave the hand the most energy without the controller
// (docs/BENCHMARKS.md, "Passivity guaranteed": 0.04 to 0.4 J) and the three that owe the most with it:
// with it each dissipates, to within 1 mJ by the bench's own account; without it the first three do not.
TEST(PassivityClosedLoop, TheWorstStressRowsDissipateWithTheControllerAndNotWithout) {
  const auto thesis = stress_cases(test::scenario("holonomic_sphere"), test::scenario("nonholonomic_needle"), 10.0);
  const auto block = layered_stress_cases(test::scenario("tissue_block_layers"));
  const auto lumbar = layered_stress_cases(test::scenario("lumbar_epidural"));
  for (const StressCase* c :
       {&row(thesis, "period x (nonholonomic_needle)", "8"),
        &row(block, "puncture force x (tissue_block_layers)", "10"), &row(lumbar, "period x (lumbar_epidural)", "8")}) {
    const auto [with, without] = dissipated_with_and_without(c->scenario);
    EXPECT_LT(without, -1e-3) << c->name << " " << c->value << ": the row should be one the controller is needed for";
    EXPECT_GE(with, -1e-3) << c->name << " " << c->value;
  }
  for (const StressCase* c :
       {&row(thesis, "period x (holonomic_sphere)", "8"), &row(thesis, "gains x (holonomic_sphere)", "0.3"),
        &row(thesis, "gains x (holonomic_sphere)", "0.1")})
    EXPECT_GE(run_closed_loop(c->scenario, false).summary.world_dissipated_min_J, -1e-3) << c->name << " " << c->value;
}

// A scripted session is passive by design: the controller never acts, not even on the first tick,
// where the held weight compensation meets a device at rest and leaves a remainder of 10⁻¹³ J.
TEST(PassivityClosedLoop, TheScriptedScenariosNeverSwitchTheControllerOn) {
  for (const char* name :
       {"holonomic_sphere", "nonholonomic_needle", "tissue_block_layers", "lumbar_epidural", "liver_biopsy"}) {
    const SimSummary& s = test::scenario_run(name, ControlLaw::Tool).summary;
    EXPECT_EQ(s.passivity_damped_s, 0.0) << name;
    EXPECT_GE(s.world_dissipated_min_J, 0.0) << name;
  }
}

// The tick the controller acts on allocates nothing either (BenchTickAllocations.* counts ticks it never
// acts on): the stress row with 16 ms ticks in tissue, where it withholds and damps for 20 s of 44.
TEST(PassivityClosedLoop, TheTicksTheControllerActsOnAllocateNothing) {
  const auto thesis = stress_cases(test::scenario("holonomic_sphere"), test::scenario("nonholonomic_needle"), 10.0);
  ClosedLoop loop(row(thesis, "period x (nonholonomic_needle)", "8").scenario);
  long allocations = 0;
  int withheld = 0, damped = 0;
  while (loop.running()) {
    const TickInput& in = loop.sense();
    needle::test::allocation_counter::start();
    const TickOutput& out = loop.tele.step(in);
    allocations += needle::test::allocation_counter::stop();
    withheld += out.passivity_share_withheld > 0.0;
    damped += out.passivity_damping_per_s > 0.0;
    loop.drive(out);
  }
  EXPECT_GT(withheld, 100);
  EXPECT_GT(damped, 100);
  EXPECT_EQ(allocations, 0);
}

}  // namespace
}  // namespace needle::haptics
