#include "haptics/realtime/teleoperation_step.hpp"

#include "haptics/realtime/virtual_state.hpp"

namespace needle::haptics {

TeleoperationStep::TeleoperationStep(const Scenario& scenario, double period_s)
    : scenario_(scenario),
      tele_(scenario.master, scenario.virt, scenario.scene, scenario.gains, period_s, scenario.virtual_substeps,
            scenario.device),
      previous_q_(VecN::Zero(scenario.master.dof())),
      applied_(VecN::Zero(scenario.master.dof())) {
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

  publish_virtual_state(tele_.world(), scenario_.base_in_world, dt_s, state);
  for (int i = 0; i < 3; ++i) state.operator_force_n[i] = in_.wrench_h[i];
  if (out.passivity_acted()) state.limits |= kLimitPassivityDamper;
  if (out.saturated) state.limits |= kLimitForce;
}

void TeleoperationStep::applied(const DeviceCommand& command) noexcept {
  for (int j = 0; j < applied_.size(); ++j)
    applied_[j] =
        command.space == CommandSpace::kJointTorque && uint32_t(j) < command.joint_count ? command.torque_nm[j] : 0.0;
  tele_.applied(applied_);
}

}  // namespace needle::haptics
