#include "haptics/model/dynamics.hpp"

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
}

void forward_dynamics(const RobotModel& model, RobotData& data, const VecN& tau, VecN& ddq) {
  data.llt.compute(data.H);
  ddq = tau - data.C * data.dq - model.damping().cwiseProduct(data.dq) - data.g;
  data.llt.solveInPlace(ddq);
}

double kinetic_energy(const RobotData& data) { return 0.5 * data.dq.dot(data.H * data.dq); }

double potential_energy(const RobotModel& model, const RobotData& data) {
  double v = 0.0;
  for (int i = 0; i < data.n; ++i) v -= model.joints[static_cast<size_t>(i)].body.mass * model.gravity.dot(data.com[i]);
  return v;
}

}  // namespace needle::haptics
