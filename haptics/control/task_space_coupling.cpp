#include "haptics/control/task_space_coupling.hpp"

namespace needle::haptics {

void task_space_coupling(const TaskCoupling& coupling, const RobotData& data, const Eigen::Vector3d& target,
                         const Eigen::Vector3d& start_direction, Eigen::Vector3d& force, VecN& tau) {
  force = coupling.stiffness_n_per_m * (target - data.tip.translation());
  const Eigen::Vector3d axis = data.tip.linear().col(0);
  const Eigen::Vector3d torque = coupling.orientation_stiffness_nm_per_rad * axis.cross(start_direction);
  Eigen::Matrix<double, 6, 1> wrench;
  wrench << force, torque;
  tau = data.J.transpose() * wrench + data.g;
}

}  // namespace needle::haptics
