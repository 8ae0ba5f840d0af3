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
  data.bias = data.C * data.dq + data.g;
}

// [[gnu::flatten]]: per-tick code, Eigen calls inlined (see kinematics.cpp).
[[gnu::flatten]] void update_bias(const RobotModel& model, RobotData& data) {
  const int n = data.n;
  // Outward pass at q̈ = 0: origin accelerations (gravity entered as a base acceleration −g),
  // then each body's force and moment about its centre of mass.
  Eigen::Vector3d accel = -model.gravity;
  Eigen::Vector3d omega_prev = Eigen::Vector3d::Zero(), omega_dot_prev = Eigen::Vector3d::Zero();
  for (int i = 0; i < n; ++i) {
    const BodyInertia& body = model.joints[static_cast<size_t>(i)].body;
    if (i > 0) {
      const Eigen::Vector3d r = data.origin[i] - data.origin[i - 1];
      accel += omega_dot_prev.cross(r) + omega_prev.cross(omega_prev.cross(r));
    }
    const Eigen::Vector3d& w = data.omega[i];
    const Eigen::Vector3d wd = omega_dot_prev + omega_prev.cross(data.axis[i] * data.dq[i]);
    const Eigen::Matrix3d& R = data.frame[i].linear();
    Eigen::Matrix3d& inertia = data.inertia_world[i];
    inertia.noalias() = R * body.inertia_com * R.transpose();
    const Eigen::Vector3d c = data.com[i] - data.origin[i];
    data.force[i] = body.mass * (accel + wd.cross(c) + w.cross(w.cross(c)));
    data.moment[i] = inertia * wd + w.cross(inertia * w);
    omega_prev = w;
    omega_dot_prev = wd;
  }
  // Inward pass: the wrench of bodies i..n−1 about origin i, projected on axis i.
  Eigen::Vector3d f = Eigen::Vector3d::Zero(), m = Eigen::Vector3d::Zero();
  for (int i = n - 1; i >= 0; --i) {
    if (i < n - 1) m += (data.origin[i + 1] - data.origin[i]).cross(f);
    f += data.force[i];
    m += data.moment[i] + (data.com[i] - data.origin[i]).cross(data.force[i]);
    data.bias[i] = data.axis[i].dot(m);
  }
}

// The inward pass of update_bias with every body at rest: each carries −m g at its centre of mass.
[[gnu::flatten]] void update_gravity(const RobotModel& model, RobotData& data) {
  Eigen::Vector3d f = Eigen::Vector3d::Zero(), m = Eigen::Vector3d::Zero();
  for (int i = data.n - 1; i >= 0; --i) {
    const Eigen::Vector3d weight = -model.joints[static_cast<size_t>(i)].body.mass * model.gravity;
    if (i < data.n - 1) m += (data.origin[i + 1] - data.origin[i]).cross(f);
    f += weight;
    m += (data.com[i] - data.origin[i]).cross(weight);
    data.g[i] = data.axis[i].dot(m);
  }
}

[[gnu::flatten]] void update_tick_dynamics(const RobotModel& model, RobotData& data) {
  update_bias(model, data);  // also the base-frame inertias
  const int n = data.n;
  // Composite body i..n−1 (a chain): mass, centre of mass and inertia about it, base frame.
  double mass = 0.0;
  Eigen::Vector3d com = Eigen::Vector3d::Zero();
  Eigen::Matrix3d inertia = Eigen::Matrix3d::Zero();
  auto shift = [](Eigen::Matrix3d& i, double m, const Eigen::Vector3d& d) {
    i.noalias() -= m * d * d.transpose();
    i.diagonal().array() += m * d.squaredNorm();
  };
  for (int i = n - 1; i >= 0; --i) {
    const double body_mass = model.joints[static_cast<size_t>(i)].body.mass;
    const double total = mass + body_mass;
    const Eigen::Vector3d c = (mass * com + body_mass * data.com[i]) / total;
    shift(inertia, mass, com - c);
    inertia += data.inertia_world[i];
    shift(inertia, body_mass, data.com[i] - c);
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
}

[[gnu::flatten]] void forward_dynamics(const RobotModel& model, RobotData& data, const VecN& tau, VecN& ddq) {
  data.llt.compute(data.H);
  ddq = tau - data.bias;
  for (int i = 0; i < data.n; ++i) ddq[i] -= model.joints[static_cast<size_t>(i)].damping * data.dq[i];
  data.llt.solveInPlace(ddq);
}

double kinetic_energy(const RobotData& data) { return 0.5 * data.dq.dot(data.H * data.dq); }

double potential_energy(const RobotModel& model, const RobotData& data) {
  double v = 0.0;
  for (int i = 0; i < data.n; ++i) v -= model.joints[static_cast<size_t>(i)].body.mass * model.gravity.dot(data.com[i]);
  return v;
}

}  // namespace needle::haptics
