// Task-space coupling for devices whose geometry differs from the virtual robot's (the
// Falcon, a translational delta; the mouse, no geometry at all), through the virtual robot's
// Jacobian (docs/DEVICES.md). A virtual coupling: the handle position, mapped into the scene,
// pulls the virtual needle tip through a spring; the virtual robot carries it as the wrench
// J^T [F; tau_r] plus gravity compensation, integrates with its constraints and a joint damper,
// and the device feels the spring's reaction. The needle's direction is held at its start
// direction by a rotational spring (position-only devices sense no orientation). Not in the
// thesis, whose master shares the virtual robot's geometry. The servo-loop adapter that reads
// the device and owns the virtual world is haptics/realtime/task_space_step.hpp.
#pragma once

#include <Eigen/Core>

#include "haptics/model/robot_data.hpp"

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

// (K, K_r; virtual robot's tip pose, J and g; target x_d, start direction d₀) =>
// (F = K (x_d − x), τ_v = Jᵀ [F; K_r x₅ × d₀] + g): the spring on the tip, and the torque that
// carries it and the direction spring (a torque about x₅ × d₀ turns x₅ towards d₀).
void task_space_coupling(const TaskCoupling& coupling, const RobotData& data, const Eigen::Vector3d& target,
                         const Eigen::Vector3d& start_direction, Eigen::Vector3d& force, VecN& tau);

}  // namespace needle::haptics
