#include "haptics/control/teleoperation_terms.hpp"

#include <algorithm>
#include <cmath>

#include "haptics/model/dynamics.hpp"
#include "haptics/model/small_cholesky.hpp"

namespace needle::haptics {

bool advance_contact_blend(ContactMode mode, double rate, ContactBlend& blend) {
  const bool new_contact = mode != ContactMode::Free && mode != blend.kind;
  if (new_contact) {
    blend.kind = mode;
    blend.weight = 0.0;
  }
  blend.weight = std::clamp(blend.weight + (mode == ContactMode::Free ? -rate : rate), 0.0, 1.0);
  if (blend.weight == 0.0) blend.kind = ContactMode::Free;
  return new_contact;
}

void filter_wrench(const Wrench& sensed, double cutoff_Hz, double T, Wrench& filtered) {
  filtered += (1.0 - std::exp(-2.0 * M_PI * cutoff_Hz * T)) * (sensed - filtered);
}

void master_free_motion_torque(const RobotGains& g, const VecN& dq, const VecN& s_a, VecN& tau) {
  tau = -g.Ka.cwiseProduct(dq) - g.Kp.cwiseProduct(s_a);
}

void virtual_free_motion_torque(const RobotGains& g, VirtualFeedback feedback, const VecN& dq, const VecN& s_a,
                                VecN& tau0, VecN& velocity_gain) {
  // ∓(K_a q̇ + K_p s_a) = −B q̇ + τ₀ with B = ±(K_a + K_p) and τ₀ = ∓K_p (s_a − q̇).
  const double sign = feedback == VirtualFeedback::Dissipative ? -1.0 : 1.0;
  velocity_gain = -sign * (g.Ka + g.Kp);
  tau0 = sign * g.Kp.cwiseProduct(s_a - dq);
}

void master_dynamics_cancellation(const RobotModel& model, RobotData& data, VecN& y_theta) {
  // Newton-Euler at q̈ = 0 with the model's own inertias: the regressor's Y θ without forming Y.
  update_bias(model, data);
  y_theta.resize(data.n);
  for (int i = 0; i < data.n; ++i) y_theta[i] = data.bias[i] + model.joints[static_cast<size_t>(i)].damping * data.dq[i];
}

void rigid_force_errors(const Eigen::Vector3d& normal, const Wrench& wrench_h, const Eigen::Vector3d& force_v, double w,
                        double T, Eigen::Vector3d& force_h_normal, ForceErrorIntegrals& integrals) {
  const Eigen::Vector3d f_h = wrench_h.head<3>();
  force_h_normal = normal * normal.dot(f_h);
  integrals.momentum_v += T * w * (force_v - force_h_normal);
  integrals.momentum_h += T * w * (force_h_normal - force_v);
}

void rigid_force_torques(const Mat6N& J_v, const Mat6N& J_m, const Eigen::Vector3d& force_h_normal,
                         const Eigen::Vector3d& force_v, const ForceErrorIntegrals& integrals, double Kf_v, double Kf_m,
                         double w, VecN& tau_v, VecN& tau_m) {
  tau_v += w * (J_v.topRows<3>().transpose() * (force_h_normal - Kf_v * integrals.momentum_v));
  tau_m -= w * (J_m.topRows<3>().transpose() * (force_v - Kf_m * integrals.momentum_h));
}

void operator_multiplier(const MatKN& A, const Mat6N& J_m, const Wrench& wrench_h, VecK& lambda_m) {
  // τ_h = J_mᵀ w_h (2.23): the simulation senses all six components, where the thesis estimated
  // them from the master's model (2.20).
  MatKK aat;
  aat.noalias() = A * A.transpose();
  SmallCholesky<kMaxConstraints> aat_factor;
  aat_factor.compute(aat);
  const VecN tau_hand = J_m.transpose() * wrench_h;
  lambda_m.noalias() = A * tau_hand;
  aat_factor.solveInPlace(lambda_m);
}

void tissue_force_error(const VecK& lambda_m, const VecK& lambda_v, double w, double T,
                        ForceErrorIntegrals& integrals) {
  integrals.lambda += T * w * (lambda_m + lambda_v);
}

void tissue_force_torques(const MatKN& A, const VecK& lambda_m, const VecK& lambda_v,
                          const ForceErrorIntegrals& integrals, double Kf_v, double Kf_m, double w, VecN& tau_v,
                          VecN& tau_m) {
  tau_v += w * (A.transpose() * (lambda_m + Kf_v * integrals.lambda));
  tau_m += w * (A.transpose() * (lambda_v + Kf_m * integrals.lambda));
}

}  // namespace needle::haptics
