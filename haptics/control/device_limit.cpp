#include "haptics/control/device_limit.hpp"

#include <Eigen/QR>

namespace needle::haptics {

bool limit_to_device(const Mat6N& J, const DeviceParams& device, VecN& tau) {
  const int m = device.actuated_joints;
  tau.tail(tau.size() - m).setZero();
  const Eigen::Matrix<double, Eigen::Dynamic, 3, 0, kMaxDof, 3> jt = J.topLeftCorner(3, m).transpose();
  const Eigen::Vector3d force = jt.colPivHouseholderQr().solve(tau.head(m));
  const double norm = force.norm();
  if (!(norm > device.force_limit_N)) return false;
  tau *= device.force_limit_N / norm;
  return true;
}

}  // namespace needle::haptics
