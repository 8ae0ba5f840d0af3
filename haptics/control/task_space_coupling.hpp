// Task-space coupling for devices whose geometry differs from the virtual robot's (the
// Falcon, a translational delta; the desk devices, no geometry at all), through the virtual
// robot's Jacobian (docs/DEVICES.md). A virtual coupling: the handle position, mapped into the
// scene, pulls the virtual needle tip through a spring; the virtual robot carries it as the
// wrench J^T [F; tau_r] plus gravity compensation, integrates with its constraints and a joint
// damper, and the device feels the spring's reaction. A rotational spring pulls the needle's
// direction towards a target direction: the start direction for a device that senses no
// orientation (the Falcon), or the start direction turned about the tip by the two angles of a
// desk device's virtual wrist. Not in the thesis, whose master shares the virtual robot's
// geometry. The servo-loop adapter that reads the device and owns the virtual world is
// haptics/realtime/task_space_step.hpp.
#pragma once

#include <Eigen/Core>

#include "haptics/model/robot_data.hpp"

namespace needle::haptics {

struct TaskCoupling {
  // Device axes to scene axes (the Falcon's z points at the user, the scene's may not). For the
  // trainee's devices the columns are the view's right, up and depth axes.
  Eigen::Matrix3d device_to_scene = Eigen::Matrix3d::Identity();
  double workspace_scale = 1.0;      // scene metres per device metre
  double stiffness_n_per_m = 300.0;  // coupling spring, scene side
  double orientation_stiffness_nm_per_rad = 0.5;
  double joint_damping_nms_per_rad = 0.05;  // implicit, on every virtual joint
  double force_scale = 1.0;                 // device newtons per scene newton
  // The reading's joints 0 and 1 are a virtual wrist's swing and tilt (the desk devices,
  // haptics/devices/desk_device.hpp): they turn the direction spring's target (wrist_direction).
  // Otherwise the target is the start direction.
  bool wrist = false;
};

// (K, K_r; virtual robot's tip pose, J and g; target x_d, target direction d) =>
// (F = K (x_d − x), τ_v = Jᵀ [F; K_r x₅ × d] + g): the spring on the tip, and the torque that
// carries it and the direction spring (a torque about x₅ × d turns x₅ towards d about the tip).
void task_space_coupling(const TaskCoupling& coupling, const RobotData& data, const Eigen::Vector3d& target,
                         const Eigen::Vector3d& target_direction, Eigen::Vector3d& force, VecN& tau);

// The start direction d₀ turned about the tip by a wrist's two angles, in the view whose right
// and up axes are the first two columns of `device_to_scene`: first a tilt by `tilt_rad` about
// f × d₀ (f the view's direction, away from the viewer; positive brings the tip towards the
// viewer, the needle's hub away), then a swing by `swing_rad` about f (positive is clockwise as
// seen: a needle pointing down swings its hub to the right). A needle pointing along f or
// against it tilts about the view's right axis instead.
Eigen::Vector3d wrist_direction(const Eigen::Matrix3d& device_to_scene, const Eigen::Vector3d& start_direction,
                                double swing_rad, double tilt_rad) noexcept;

}  // namespace needle::haptics
