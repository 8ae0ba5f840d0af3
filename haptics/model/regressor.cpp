#include "haptics/model/regressor.hpp"

namespace needle::haptics {

ParamVec parameter_vector(const RobotModel& model) {
  const int n = model.dof();
  ParamVec theta(ParamVec::Zero((kParamsPerBody + 1) * n));
  for (int i = 0; i < n; ++i) {
    const JointModel& j = model.joints[static_cast<size_t>(i)];
    const BodyInertia& b = j.body;
    // Inertia about the joint-frame origin (parallel-axis theorem).
    const Eigen::Matrix3d io =
        b.inertia_com + b.mass * (b.com.squaredNorm() * Eigen::Matrix3d::Identity() - b.com * b.com.transpose());
    theta.segment<kParamsPerBody>(kParamsPerBody * i) << b.mass, b.mass * b.com, io(0, 0), io(0, 1), io(0, 2), io(1, 1),
        io(1, 2), io(2, 2);
    theta[kParamsPerBody * n + i] = j.damping;
  }
  return theta;
}

void inverse_dynamics(const RobotModel& model, RobotData& data, const ParamVec& theta, const VecN& ddq, VecN& tau) {
  const int n = data.n;
  // Outward pass: body-origin accelerations, gravity entered as a base acceleration −g.
  Eigen::Vector3d omega_prev = Eigen::Vector3d::Zero(), omega_dot_prev = Eigen::Vector3d::Zero();
  for (int i = 0; i < n; ++i) {
    if (i == 0) {
      data.accel[i] = -model.gravity;
    } else {
      const Eigen::Vector3d r = data.origin[i] - data.origin[i - 1];
      data.accel[i] = data.accel[i - 1] + omega_dot_prev.cross(r) + omega_prev.cross(omega_prev.cross(r));
    }
    data.omega_dot[i] = omega_dot_prev + data.axis[i] * ddq[i] + omega_prev.cross(data.axis[i] * data.dq[i]);
    omega_prev = data.omega[i];
    omega_dot_prev = data.omega_dot[i];

    const auto p = theta.segment<kParamsPerBody>(kParamsPerBody * i);
    const Eigen::Matrix3d R = data.frame[i].linear();
    const Eigen::Vector3d h = R * Eigen::Vector3d(p[1], p[2], p[3]);
    Eigen::Matrix3d ib;
    ib << p[4], p[5], p[6], p[5], p[7], p[8], p[6], p[8], p[9];
    const Eigen::Matrix3d io = R * ib * R.transpose();
    const Eigen::Vector3d& w = data.omega[i];
    const Eigen::Vector3d& wd = data.omega_dot[i];
    data.force[i] = p[0] * data.accel[i] + wd.cross(h) + w.cross(w.cross(h));
    data.moment[i] = io * wd + w.cross(io * w) + h.cross(data.accel[i]);
  }
  // Inward pass: wrench about each joint origin, projected on its axis.
  tau.resize(n);
  Eigen::Vector3d f = Eigen::Vector3d::Zero(), m = Eigen::Vector3d::Zero();
  for (int i = n - 1; i >= 0; --i) {
    if (i < n - 1) m += (data.origin[i + 1] - data.origin[i]).cross(f);
    f += data.force[i];
    m += data.moment[i];
    tau[i] = data.axis[i].dot(m) + theta[kParamsPerBody * n + i] * data.dq[i];
  }
}

void regressor(const RobotModel& model, RobotData& data, const VecN& ddq, RegressorMat& Y) {
  const int n = data.n;
  const int columns = (kParamsPerBody + 1) * n;
  Y.setZero(n, columns);
  VecN column(n);
  for (int k = 0; k < columns; ++k) {
    data.unit_params.setZero(columns);
    data.unit_params[k] = 1.0;
    inverse_dynamics(model, data, data.unit_params, ddq, column);
    Y.col(k) = column;
  }
}

}  // namespace needle::haptics
