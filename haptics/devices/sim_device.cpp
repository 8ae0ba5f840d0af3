#include "haptics/devices/sim_device.hpp"

#include <algorithm>

namespace needle::haptics {
namespace {

// The monitor's torque bound for an actuated joint: the plant already limits its motors' torques to
// force_limit_N at the tip in the nominal pose (haptics/control/device_limit.hpp); this bound (that
// force on a 0.5 m lever, longer than the Omni's reach) only catches commands no such torque could explain.
constexpr double kLeverBoundM = 0.5;

}  // namespace

SimDevice::SimDevice(const Scenario& scenario, double period_s)
    : scenario_(scenario),
      plant_(scenario.master, scenario.device, scenario.hand, scenario.master_integrator, scenario.master_substeps),
      sensor_(scenario.sensor),
      period_s_(period_s),
      tau_(VecN::Zero(scenario.master.dof())) {
  const int n = scenario.master.dof();
  caps_.name = "sim";
  caps_.command_space = CommandSpace::kJointTorque;
  caps_.joint_count = static_cast<uint32_t>(n);
  caps_.actuated_axes = static_cast<uint32_t>(scenario.device.actuated_joints);
  caps_.max_force_n = scenario.device.force_limit_N;
  for (int j = 0; j < std::min(n, kMaxDeviceJoints); ++j)
    caps_.max_torque_nm[j] = j < scenario.device.actuated_joints ? scenario.device.force_limit_N * kLeverBoundM : 0.0;
  caps_.senses_force = true;
  if (scenario.thumb) thumb_.emplace(*scenario.thumb);
}

void SimDevice::open() {
  const int n = scenario_.master.dof();
  plant_.reset(scenario_.q0, VecN::Zero(n));
  sensor_.reset(Wrench::Zero());
  ticks_ = 0;
  if (thumb_) thumb_->reset();
}

void SimDevice::read(DeviceReading& out) noexcept {
  const int n = static_cast<int>(caps_.joint_count);
  const Wrench sensed = sensor_.read(plant_.hand_wrench(), period_s_);
  out.sequence = ticks_ + 1;
  out.connected = 1;
  out.joint_count = caps_.joint_count;
  out.has_joint_velocity = 1;
  out.has_sensed_force = 1;
  for (int j = 0; j < n; ++j) {
    out.joint_rad[j] = plant_.q()[j];
    out.joint_velocity_rad_s[j] = plant_.dq()[j];
  }
  const Eigen::Vector3d tip = plant_.data().tip.translation();
  for (int i = 0; i < 3; ++i) {
    out.position_m[i] = tip[i];
    out.sensed_force_n[i] = sensed[i];
    out.sensed_torque_nm[i] = sensed[3 + i];
  }
  if (thumb_) {
    out.plunger_input = uint32_t(PlungerInput::kThumbForce);
    out.plunger_force_n = thumb_->force(static_cast<double>(ticks_) * period_s_);
  }
}

void SimDevice::write(const DeviceCommand& command) noexcept {
  const int n = static_cast<int>(caps_.joint_count);
  for (int j = 0; j < n; ++j) tau_[j] = command.space == CommandSpace::kJointTorque ? command.torque_nm[j] : 0.0;
  // Time as tick x period, as the closed-loop simulation counts it (no accumulated rounding).
  const double t = static_cast<double>(ticks_) * period_s_;
  if (thumb_) {
    thumb_->feel(t, command.plunger_travel_m, period_s_);
    if (thumb_->reaction_due(t))
      thumb_->begin_reaction(t, plant_.data().tip.translation(), plant_.data().tip.linear().col(0));
  }
  plant_.advance(tau_, thumb_ ? thumb_->trajectory(scenario_.trajectory) : scenario_.trajectory, t, period_s_);
  ++ticks_;
}

}  // namespace needle::haptics
