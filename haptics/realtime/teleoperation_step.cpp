#include "haptics/realtime/teleoperation_step.hpp"

#include <Eigen/Geometry>
#include <algorithm>

namespace needle::haptics {
namespace {

ContactState contact_of(ContactMode mode) {
  switch (mode) {
    case ContactMode::Holonomic: return ContactState::kRigidSurface;
    case ContactMode::Nonholonomic: return ContactState::kTissue;
    case ContactMode::Free: break;
  }
  return ContactState::kFree;
}

}  // namespace

TeleoperationStep::TeleoperationStep(const Scenario& scenario, double period_s)
    : scenario_(scenario),
      tele_(scenario.master, scenario.virt, scenario.scene, scenario.gains, period_s, scenario.virtual_substeps),
      previous_q_(VecN::Zero(scenario.master.dof())) {
  const int n = scenario.master.dof();
  tele_.reset(scenario.q0, VecN::Zero(n));
  in_.q_m = VecN::Zero(n);
  in_.dq_m = VecN::Zero(n);
}

void TeleoperationStep::step(const DeviceReading& reading, double dt_s, DeviceCommand& command,
                             ToolSnapshot& state) noexcept {
  const int n = scenario_.master.dof();
  for (int j = 0; j < n; ++j) in_.q_m[j] = reading.joint_rad[j];
  if (reading.has_joint_velocity) {
    for (int j = 0; j < n; ++j) in_.dq_m[j] = reading.joint_velocity_rad_s[j];
  } else {
    in_.dq_m = have_previous_ ? VecN((in_.q_m - previous_q_) / dt_s) : VecN::Zero(n);
  }
  previous_q_ = in_.q_m;
  have_previous_ = true;
  for (int i = 0; i < 3; ++i) {
    in_.wrench_h[i] = reading.has_sensed_force ? reading.sensed_force_n[i] : 0.0;
    in_.wrench_h[3 + i] = reading.has_sensed_force ? reading.sensed_torque_nm[i] : 0.0;
  }

  const TickOutput& out = tele_.step(in_);

  command.space = CommandSpace::kJointTorque;
  command.joint_count = static_cast<uint32_t>(n);
  for (int j = 0; j < n; ++j) command.torque_nm[j] = j < scenario_.device.actuated_joints ? out.tau_m[j] : 0.0;

  const VirtualWorld& world = tele_.world();
  const ContactReport& c = world.report();
  const Eigen::Vector3d tip = world.data().tip.translation() + scenario_.base_in_world;
  const Eigen::Quaterniond orientation(world.data().tip.linear());
  state.time_s += dt_s;
  state.joint_count = static_cast<uint32_t>(std::min(world.q().size(), Eigen::Index{kMaxSnapshotJoints}));
  for (uint32_t j = 0; j < state.joint_count; ++j) {
    state.virtual_q[j] = world.q()[j];
    state.virtual_dq[j] = world.dq()[j];
  }
  for (int i = 0; i < 3; ++i) {
    state.needle_tip_m[i] = tip[i];
    state.operator_force_n[i] = in_.wrench_h[i];
    state.environment_force_n[i] = c.force_rigid[i];
  }
  state.needle_orientation[0] = orientation.w();
  state.needle_orientation[1] = orientation.x();
  state.needle_orientation[2] = orientation.y();
  state.needle_orientation[3] = orientation.z();
  state.contact = contact_of(c.mode);
  // The scene holds one rigid surface (constraint 0) and one tissue (constraint 1).
  state.active_constraint = c.mode == ContactMode::Free ? -1 : c.mode == ContactMode::Holonomic ? 0 : 1;
  state.multiplier_count = c.mode == ContactMode::Free ? 0 : c.mode == ContactMode::Holonomic ? 1 : 2;
  const bool tissue = c.mode == ContactMode::Nonholonomic;
  state.multipliers[0] = c.mode == ContactMode::Holonomic ? c.lambda_rigid : tissue ? c.lambda_tissue[0] : 0.0;
  state.multipliers[1] = tissue ? c.lambda_tissue[1] : 0.0;
}

}  // namespace needle::haptics
