#include "haptics/control/device_limit.hpp"

#include <Eigen/QR>
#include <algorithm>
#include <cmath>
#include <limits>

#include "haptics/model/kinematics.hpp"

namespace needle::haptics {

DeviceLimit device_limit(const RobotModel& model, const DeviceParams& device) {
  const int n = model.dof(), m = device.actuated_joints;
  VecN q = VecN::Zero(n);
  for (int i = 0; i < n; ++i) q[i] = device.nominal_pose_rad[static_cast<size_t>(i)];
  RobotData data(model);
  update_frames(model, data, q, VecN::Zero(n));
  const Eigen::MatrixXd jt = data.J.topLeftCorner(3, m).transpose();  // τ_a = J_aᵀ F
  DeviceLimit limit;
  limit.force_per_torque = jt.completeOrthogonalDecomposition().pseudoInverse();
  limit.force_limit_N = device.force_limit_N;
  limit.actuated_joints = m;
  return limit;
}

double limit_to_device(const DeviceLimit& limit, VecN& tau) {
  const int m = limit.actuated_joints;
  tau.tail(tau.size() - m).setZero();
  const double force = (limit.force_per_torque * tau.head(m)).norm();
  if (!(force > limit.force_limit_N)) return 1.0;
  const double kappa = limit.force_limit_N / force;
  tau *= kappa;
  return kappa;
}

double room_within_limit(const DeviceLimit& limit, const VecN& tau, const VecN& h) {
  const int m = limit.actuated_joints;
  const Eigen::Vector3d a = limit.force_per_torque * tau.head(m), b = limit.force_per_torque * h.head(m);
  const double bb = b.squaredNorm(), ab = a.dot(b);
  if (!(bb > 0.0)) return std::numeric_limits<double>::infinity();
  // ‖a − βb‖² = F² at the larger root; the smaller is ≤ 0 while ‖a‖ ≤ F.
  const double disc = ab * ab - bb * (a.squaredNorm() - limit.force_limit_N * limit.force_limit_N);
  return disc > 0.0 ? std::max(0.0, (ab + std::sqrt(disc)) / bb) : 0.0;
}

}  // namespace needle::haptics
