#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "haptics/realtime/sim_session.hpp"
#include "haptics/sim/closed_loop.hpp"
#include "test_realtime_fakes.hpp"
#include "tests/support/test_paths.hpp"

namespace needle::haptics {
namespace {

// The `sim` device and the controller, run through the real-time loop's tick with the safety
// monitor at the device's default limits, must be the closed-loop simulation of the physics
// (haptics/sim/closed_loop.cpp) number for number: the limits never need to act on the
// thesis's experiments, and the loop adds nothing of its own.
void expect_loop_reproduces_closed_loop(const char* scenario_file, double seconds) {
  Scenario scenario = load_scenario(test::source_dir().string() + "/assets/scenarios/" + scenario_file);
  scenario.duration_s = seconds;
  const SimResult reference = run_closed_loop(scenario, true);
  ASSERT_TRUE(reference.summary.faults.empty());

  SimSession sim(scenario, 1.0 / scenario.period_s);
  sim.device().open();
  testing::TickRig rig(sim.device(), sim.step(), safety_limits_for(sim.device().capabilities()), 16);

  const int n = scenario.master.dof();
  const int actuated = scenario.device.actuated_joints;
  int mismatches = 0;
  bool touched = false;
  for (std::size_t k = 0; k < reference.ticks.size(); ++k) {
    rig.run(k, 1, scenario.period_s);
    const TickSample& s = rig.tick.last_sample();
    const TickRecord& r = reference.ticks[k];
    for (int j = 0; j < n; ++j) {
      mismatches += s.state.virtual_q[j] != r.q_v[j];
      mismatches += sim.device().plant().q()[j] != r.q_m[j];
      mismatches += s.command.torque_nm[j] != (j < actuated ? r.tau_m[j] : 0.0);
    }
    for (int i = 0; i < 3; ++i) mismatches += s.state.needle_tip_m[i] != r.x_v[i];
    touched = touched || s.state.contact != ContactState::kFree;
    ASSERT_EQ(mismatches, 0) << "first difference at tick " << k;
  }
  EXPECT_TRUE(touched) << "the run reached the constraint";
  EXPECT_EQ(rig.safety.fault(), FaultCause::kNone);
}

TEST(DeviceSim, LoopTickReproducesTheClosedLoopSimulationOnTheSphere) {
  expect_loop_reproduces_closed_loop("holonomic_sphere.json", 10.0);
}

TEST(DeviceSim, LoopTickReproducesTheClosedLoopSimulationInTissue) {
  expect_loop_reproduces_closed_loop("nonholonomic_needle.json", 12.0);
}

TEST(DeviceSim, ReadsJointStateAndSensedWrench) {
  SimSession sim(test::source_dir().string() + "/assets/scenarios/holonomic_sphere.json", 1000.0);
  const Scenario& scenario = sim.scenario();
  SimDevice& device = sim.device();
  device.open();
  DeviceReading r;
  device.read(r);
  EXPECT_EQ(r.joint_count, static_cast<uint32_t>(scenario.master.dof()));
  for (int j = 0; j < scenario.master.dof(); ++j) EXPECT_EQ(r.joint_rad[j], scenario.q0[j]);
  EXPECT_EQ(r.has_joint_velocity, 1u);
  EXPECT_EQ(r.has_sensed_force, 1u);
  EXPECT_EQ(device.capabilities().command_space, CommandSpace::kJointTorque);
  EXPECT_EQ(device.capabilities().max_torque_nm[scenario.device.actuated_joints], 0.0) << "unactuated joints";
}

}  // namespace
}  // namespace needle::haptics
