// The task-space coupling (haptics/control/task_space_coupling.hpp) as the loop's ServoStep, for
// position devices (falcon, and the desk devices: mouse, keyboard, gamepad): maps the handle into
// the scene and, for a desk device, its virtual wrist onto the needle's target direction; applies the coupling to
// the virtual robot it owns (VirtualWorld: rigid surface by the penalty method, tissue by the
// nonholonomic multipliers), commands the spring's reaction in device axes and publishes the
// virtual robot's state.
#pragma once

#include <Eigen/Core>

#include "haptics/control/task_space_coupling.hpp"
#include "haptics/control/virtual_world.hpp"
#include "haptics/realtime/servo_step.hpp"
#include "haptics/sim/scenario.hpp"

namespace needle::haptics {

class TaskSpaceStep : public ServoStep {
 public:
  // Uses the scenario's virtual robot, scene, constraint gains, q0 and base placement. The
  // device position of the first reading maps onto the virtual tip's start position, and with
  // TaskCoupling::wrist its wrist angles onto the needle's start direction.
  TaskSpaceStep(const Scenario& scenario, const TaskCoupling& coupling);

  void step(const DeviceReading& reading, double dt_s, DeviceCommand& command, ToolSnapshot& state) noexcept override;

  const VirtualWorld& world() const noexcept { return world_; }
  const TaskCoupling& coupling() const noexcept { return coupling_; }
  // Where the tool started, robot base frame: the tip and the needle axis x5.
  const Eigen::Vector3d& start_tip() const noexcept { return tip_start_; }
  const Eigen::Vector3d& start_direction() const noexcept { return direction_start_; }
  // The handle position of the last reading mapped into the robot's base frame.
  const Eigen::Vector3d& target() const noexcept { return target_; }
  // The direction the needle is pulled towards: the start direction, turned by a wrist.
  const Eigen::Vector3d& target_direction() const noexcept { return target_direction_; }

 private:
  const Scenario& scenario_;
  TaskCoupling coupling_;
  int substeps_;
  VirtualWorld world_;
  RobotData data_;  // the virtual robot at the world's state: Jacobian and gravity of this tick
  Eigen::Vector3d tip_start_, direction_start_, device_start_, target_, target_direction_;
  double wrist_start_[2] = {0.0, 0.0};
  bool started_ = false;
  VecN tau_, damping_;
};

}  // namespace needle::haptics
