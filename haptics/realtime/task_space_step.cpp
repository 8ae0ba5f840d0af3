#include "haptics/realtime/task_space_step.hpp"

#include "haptics/model/dynamics.hpp"
#include "haptics/model/kinematics.hpp"
#include "haptics/realtime/virtual_state.hpp"

namespace needle::haptics {

TaskSpaceStep::TaskSpaceStep(const Scenario& scenario, const TaskCoupling& coupling)
    : scenario_(scenario),
      coupling_(coupling),
      substeps_(scenario.virtual_substeps),
      world_(scenario.virt, scenario.scene, scenario.gains.gpm, scenario.gains.nonholonomic),
      data_(scenario.virt),
      device_start_(Eigen::Vector3d::Zero()),
      target_(Eigen::Vector3d::Zero()) {
  const int n = scenario.virt.dof();
  world_.reset(scenario.q0.head(n), VecN::Zero(n));
  update_kinematics(scenario.virt, data_, world_.q(), world_.dq());
  tip_start_ = data_.tip.translation();
  direction_start_ = data_.tip.linear().col(0);
  target_ = tip_start_;
  target_direction_ = direction_start_;
  tau_ = VecN::Zero(n);
  damping_ = VecN::Constant(n, coupling.joint_damping_nms_per_rad);
}

void TaskSpaceStep::step(const DeviceReading& reading, double dt_s, DeviceCommand& command,
                         ToolSnapshot& state) noexcept {
  const Eigen::Vector3d handle(reading.position_m[0], reading.position_m[1], reading.position_m[2]);
  if (!started_) {
    device_start_ = handle;
    for (int i = 0; i < 2; ++i) wrist_start_[i] = reading.joint_rad[i];
    started_ = true;
  }
  target_ = tip_start_ + coupling_.workspace_scale * (coupling_.device_to_scene * (handle - device_start_));
  if (coupling_.wrist && reading.joint_count >= 2)
    target_direction_ = wrist_direction(coupling_.device_to_scene, direction_start_,
                                        reading.joint_rad[0] - wrist_start_[0], reading.joint_rad[1] - wrist_start_[1]);

  // Kinematics and gravity evaluated here rather than read from the world, whose data may
  // hold only what its own integration needed.
  update_kinematics(scenario_.virt, data_, world_.q(), world_.dq());
  update_dynamics(scenario_.virt, data_);
  Eigen::Vector3d force;
  task_space_coupling(coupling_, data_, target_, target_direction_, force, tau_);
  world_.advance(tau_, damping_, dt_s, substeps_);

  // The handle feels the spring's reaction, in device axes, where the device exerts force: a desk
  // device's command space is none (ServoTick sets it from the capabilities), so it is sent nothing
  // and nothing is held back at a limit it does not have (the forces are shown on screen instead).
  if (command.space == CommandSpace::kTaskForce) {
    const Eigen::Vector3d reaction = -coupling_.force_scale * (coupling_.device_to_scene.transpose() * force);
    for (int i = 0; i < 3; ++i) command.force_n[i] = reaction[i];
  }

  publish_virtual_state(world_, scenario_.base_in_world, dt_s, state);
  for (int i = 0; i < 3; ++i) state.operator_force_n[i] = force[i];
}

}  // namespace needle::haptics
