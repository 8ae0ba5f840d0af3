// Task-space coupling for devices whose geometry differs from the virtual robot's (the
// Falcon, a translational delta; the mouse, no geometry at all), through the virtual robot's
// Jacobian (docs/DEVICES.md). A virtual coupling: the handle position, mapped into the scene,
// pulls the virtual needle tip through a spring; the virtual robot carries it as the wrench
// J^T [F; tau_r] plus gravity compensation, integrates with its constraints (VirtualWorld:
// rigid surface by the penalty method, tissue by the nonholonomic multipliers), and the device
// feels the spring's reaction. The needle's direction is held at its start direction by a
// rotational spring (position-only devices sense no orientation).
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "haptics/control/virtual_world.hpp"
#include "haptics/realtime/servo_step.hpp"
#include "haptics/sim/scenario.hpp"

namespace needle::haptics {

struct TaskCoupling {
  // Device axes to scene axes (the Falcon's z points at the user, the scene's may not).
  Eigen::Matrix3d device_to_scene = Eigen::Matrix3d::Identity();
  double workspace_scale = 1.0;          // scene metres per device metre
  double stiffness_n_per_m = 300.0;      // coupling spring, scene side
  double orientation_stiffness_nm_per_rad = 0.5;
  double joint_damping_nms_per_rad = 0.05;  // implicit, on every virtual joint
  double force_scale = 1.0;              // device newtons per scene newton
};

class TaskSpaceStep : public ServoStep {
 public:
  // Uses the scenario's virtual robot, scene, constraint gains, q0 and base placement. The
  // device position of the first reading maps onto the virtual tip's start position.
  TaskSpaceStep(const Scenario& scenario, const TaskCoupling& coupling);

  void step(const DeviceReading& reading, double dt_s, DeviceCommand& command, ToolSnapshot& state) noexcept override;

  const VirtualWorld& world() const noexcept { return world_; }
  // Where the tool started, robot base frame: the tip and the needle axis x5.
  const Eigen::Vector3d& start_tip() const noexcept { return tip_start_; }
  const Eigen::Vector3d& start_direction() const noexcept { return direction_start_; }
  // The handle position of the last reading mapped into the robot's base frame.
  const Eigen::Vector3d& target() const noexcept { return target_; }

 private:
  const Scenario& scenario_;
  TaskCoupling coupling_;
  int substeps_;
  VirtualWorld world_;
  RobotData data_;  // the virtual robot at the world's state: Jacobian and gravity of this tick
  Eigen::Vector3d tip_start_, direction_start_, device_start_, target_;
  bool started_ = false;
  VecN tau_, damping_;
};

}  // namespace needle::haptics
