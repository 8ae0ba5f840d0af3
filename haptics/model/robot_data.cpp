#include "haptics/model/robot_data.hpp"

namespace needle::haptics {

RobotData::RobotData(const RobotModel& model)
    : n(model.dof()),
      q(VecN::Zero(n)),
      dq(VecN::Zero(n)),
      tip(Eigen::Isometry3d::Identity()),
      tip_twist(Eigen::Matrix<double, 6, 1>::Zero()),
      J(Mat6N::Zero(6, n)),
      Jdot(Mat6N::Zero(6, n)),
      H(MatN::Zero(n, n)),
      C(MatN::Zero(n, n)),
      g(VecN::Zero(n)),
      bias(VecN::Zero(n)),
      unit_params(ParamVec::Zero((kParamsPerBody + 1) * n)) {
  frame.fill(Eigen::Isometry3d::Identity());
  inertia_world.fill(Eigen::Matrix3d::Zero());
  for (auto* a : {&axis, &origin, &origin_velocity, &omega, &com, &omega_dot, &accel, &force, &moment})
    a->fill(Eigen::Vector3d::Zero());
  J_com.fill(Mat6N::Zero(6, n));
  Jdot_com.fill(Mat6N::Zero(6, n));
}

}  // namespace needle::haptics
