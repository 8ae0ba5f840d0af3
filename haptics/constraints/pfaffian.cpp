#include "haptics/constraints/pfaffian.hpp"

namespace needle::haptics {

void needle_pfaffian(const Eigen::Matrix3d& tip_rotation, const Eigen::Vector3d& tip_omega, TaskPfaffian& out) {
  out.A_x.setZero(2, 6);
  out.A_x_dot.setZero(2, 6);
  for (int row = 0; row < 2; ++row) {
    const Eigen::Vector3d axis = tip_rotation.col(row + 1);  // y₅, then z₅
    out.A_x.row(row).head<3>() = axis.transpose();
    out.A_x_dot.row(row).head<3>() = tip_omega.cross(axis).transpose();
  }
}

// [[gnu::flatten]]: per-tick code, Eigen calls inlined (see kinematics.cpp).
[[gnu::flatten]] void project_pfaffian(const TaskPfaffian& task, const Mat6N& J, const Mat6N& J_dot, MatKN& A,
                                       MatKN& A_dot) {
  A.noalias() = task.A_x * J;
  A_dot.noalias() = task.A_x_dot * J;
  A_dot.noalias() += task.A_x * J_dot;
}

}  // namespace needle::haptics
