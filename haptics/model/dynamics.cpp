#include "haptics/model/dynamics.hpp"

#include "haptics/model/regressor.hpp"

namespace needle::haptics {

namespace {
Eigen::Matrix3d skew(const Eigen::Vector3d& w) {
  Eigen::Matrix3d s;
  s << 0, -w.z(), w.y(), w.z(), 0, -w.x(), -w.y(), w.x(), 0;
  return s;
}
}  // namespace

void update_dynamics(const RobotModel& model, RobotData& data) {
  const int n = data.n;
  data.H.setZero(n, n);
  data.C.setZero(n, n);
  data.g.setZero(n);
  for (int i = 0; i < n; ++i) {
    const BodyInertia& body = model.joints[static_cast<size_t>(i)].body;
    const Eigen::Matrix3d R = data.frame[i].linear();
    const Eigen::Matrix3d inertia = R * body.inertia_com * R.transpose();
    const auto Jv = data.J_com[i].topRows<3>();
    const auto Jw = data.J_com[i].bottomRows<3>();
    const auto Jv_dot = data.Jdot_com[i].topRows<3>();
    const auto Jw_dot = data.Jdot_com[i].bottomRows<3>();
    data.H.noalias() += body.mass * Jv.transpose() * Jv;
    data.H.noalias() += Jw.transpose() * inertia * Jw;
    data.C.noalias() += body.mass * Jv.transpose() * Jv_dot;
    data.C.noalias() += Jw.transpose() * inertia * Jw_dot;
    data.C.noalias() += Jw.transpose() * (skew(data.omega[i]) * inertia) * Jw;
    data.g.noalias() -= body.mass * Jv.transpose() * model.gravity;
  }
  data.bias = data.C * data.dq + data.g;
}

void update_tick_dynamics(const RobotModel& model, RobotData& data) {
  const int n = data.n;
  // Composite body i..n−1 (a chain): mass, centre of mass and inertia about it, base frame.
  double mass = 0.0;
  Eigen::Vector3d com = Eigen::Vector3d::Zero();
  Eigen::Matrix3d inertia = Eigen::Matrix3d::Zero();
  auto shifted = [](const Eigen::Matrix3d& i, double m, const Eigen::Vector3d& d) {
    return Eigen::Matrix3d(i + m * (d.squaredNorm() * Eigen::Matrix3d::Identity() - d * d.transpose()));
  };
  for (int i = n - 1; i >= 0; --i) {
    const BodyInertia& body = model.joints[static_cast<size_t>(i)].body;
    const Eigen::Matrix3d R = data.frame[i].linear();
    const double total = mass + body.mass;
    const Eigen::Vector3d c = (mass * com + body.mass * data.com[i]) / total;
    inertia = shifted(inertia, mass, com - c) + shifted(R * body.inertia_com * R.transpose(), body.mass, data.com[i] - c);
    mass = total;
    com = c;
    // Unit rate of joint i moves the composite rigidly about axis z_i through p_i; H_ji is z_j
    // dotted with its angular momentum about p_j.
    const Eigen::Vector3d& z = data.axis[i];
    const Eigen::Vector3d momentum = mass * z.cross(com - data.origin[i]);
    const Eigen::Vector3d spin = inertia * z;
    for (int j = 0; j <= i; ++j) {
      data.H(j, i) = data.axis[j].dot(spin + (com - data.origin[j]).cross(momentum));
      data.H(i, j) = data.H(j, i);
    }
  }
  // bias = τ(q, q̇, q̈ = 0) − D q̇.
  inverse_dynamics(model, data, data.theta, data.zero_n, data.bias);
  data.bias -= data.theta.tail(n).cwiseProduct(data.dq);
}

void forward_dynamics(const RobotModel& model, RobotData& data, const VecN& tau, VecN& ddq) {
  data.llt.compute(data.H);
  ddq = tau - data.bias - model.damping().cwiseProduct(data.dq);
  data.llt.solveInPlace(ddq);
}

double kinetic_energy(const RobotData& data) { return 0.5 * data.dq.dot(data.H * data.dq); }

double potential_energy(const RobotModel& model, const RobotData& data) {
  double v = 0.0;
  for (int i = 0; i < data.n; ++i) v -= model.joints[static_cast<size_t>(i)].body.mass * model.gravity.dot(data.com[i]);
  return v;
}

}  // namespace needle::haptics
