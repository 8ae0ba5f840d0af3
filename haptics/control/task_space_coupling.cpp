#include "haptics/control/task_space_coupling.hpp"

#include <Eigen/Geometry>

namespace needle::haptics {

void task_space_coupling(const TaskCoupling& coupling, const RobotData& data, const Eigen::Vector3d& target,
                         const Eigen::Vector3d& target_direction, Eigen::Vector3d& force, VecN& tau) {
  force = coupling.stiffness_n_per_m * (target - data.tip.translation());
  const Eigen::Vector3d axis = data.tip.linear().col(0);
  const Eigen::Vector3d torque = coupling.orientation_stiffness_nm_per_rad * axis.cross(target_direction);
  Eigen::Matrix<double, 6, 1> wrench;
  wrench << force, torque;
  tau = data.J.transpose() * wrench + data.g;
}

Eigen::Vector3d wrist_direction(const Eigen::Matrix3d& device_to_scene, const Eigen::Vector3d& start_direction,
                                double swing_rad, double tilt_rad) noexcept {
  const Eigen::Vector3d right = device_to_scene.col(0).normalized();
  const Eigen::Vector3d away = device_to_scene.col(1).cross(device_to_scene.col(0)).normalized();  // up × right
  const Eigen::Vector3d across = away.cross(start_direction);
  const Eigen::Vector3d tilt_axis = across.norm() > 1e-9 ? Eigen::Vector3d(across.normalized()) : right;
  return Eigen::AngleAxisd(swing_rad, away) * (Eigen::AngleAxisd(tilt_rad, tilt_axis) * start_direction);
}

}  // namespace needle::haptics
