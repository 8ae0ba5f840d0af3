// The teleoperation controller (thesis 3.2) one equation group at a time: Teleoperation::step
// calls these in order. Each states what it reads and what it writes; signs and forms are the
// corrected ones of docs/CONTROLLER.md, which maps every equation to its function and test.
// Functions that take τ by reference add their terms, times the blend weight w, to it. All
// allocation-free, and defined here so that step() ([[gnu::flatten]]) inlines them.
#pragma once

#include <algorithm>
#include <cmath>

#include "haptics/control/gains.hpp"
#include "haptics/control/virtual_world.hpp"
#include "haptics/model/dynamics.hpp"
#include "haptics/model/small_cholesky.hpp"

namespace needle::haptics {

using Wrench = Eigen::Matrix<double, 6, 1>;

// Which contact's terms are on, and how far (not in the thesis: docs/CONTROLLER.md, blending).
struct ContactBlend {
  ContactMode kind = ContactMode::Free;  // the contact whose terms are blending
  double weight = 0.0;                   // w: 0 free ... 1 contact terms fully on
};

// The integrals of the force errors, restarted at each new contact.
struct ForceErrorIntegrals {
  Eigen::Vector3d momentum_h = Eigen::Vector3d::Zero();  // Δp_h (3.19)
  Eigen::Vector3d momentum_v = Eigen::Vector3d::Zero();  // Δp_v (3.19)
  VecK lambda = VecK::Zero(2);                           // E = ∫(λ_m + λ_v) dt (3.26)
};

// (contact mode now, T / switch time; blend) => (blend; true at a new contact)   contact blending:
// w ramps toward 1 in contact, toward 0 in free motion; a new contact restarts w (and the caller's
// force integrals).
inline bool advance_contact_blend(ContactMode mode, double rate, ContactBlend& blend) {
  const bool new_contact = mode != ContactMode::Free && mode != blend.kind;
  if (new_contact) {
    blend.kind = mode;
    blend.weight = 0.0;
  }
  blend.weight = std::clamp(blend.weight + (mode == ContactMode::Free ? -rate : rate), 0.0, 1.0);
  if (blend.weight == 0.0) blend.kind = ContactMode::Free;
  return new_contact;
}

// (sensed w_h, cutoff, T; filtered) => (filtered)   first-order low-pass of the wrench entering
// the force terms (not in the thesis: docs/CONTROLLER.md, sensed-wrench filter).
inline void filter_wrench(const Wrench& sensed, double cutoff_Hz, double T, Wrench& filtered) {
  filtered += (1.0 - std::exp(-2.0 * M_PI * cutoff_Hz * T)) * (sensed - filtered);
}

// (K_am, K_pm, q̇_m, s_am) => (τ_m = −K_am q̇_m − K_pm s_am)   (3.13), as printed.
inline void master_free_motion_torque(const RobotGains& g, const VecN& dq, const VecN& s_a, VecN& tau) {
  tau = -g.Ka.cwiseProduct(dq) - g.Kp.cwiseProduct(s_a);
}

// (K_av, K_pv, sign, q̇_v, s_av) => (τ_v0, B), τ_v = τ_v0 − B q̇_v = −K_av q̇_v − K_pv s_av   (3.14),
// dissipative sign (AsPrinted flips it), split so that the virtual world applies −B q̇_v implicitly:
// B = ±(K_a + K_p), τ_v0 = ∓K_p (s_a − q̇).
inline void virtual_free_motion_torque(const RobotGains& g, VirtualFeedback feedback, const VecN& dq, const VecN& s_a,
                                       VecN& tau0, VecN& velocity_gain) {
  const double sign = feedback == VirtualFeedback::Dissipative ? -1.0 : 1.0;
  velocity_gain = -sign * (g.Ka + g.Kp);
  tau0 = sign * g.Kp.cwiseProduct(s_a - dq);
}

// (master model, data after update_frames, w; τ_m) => (τ_m += w Y_m(q_m, q̇_m, 0) θ_m)   the dynamic
// cancellation of (3.20), (3.27): Y θ = C_m q̇_m + D_m q̇_m + g_m, without H_m q̈_m (q̈_m is not
// measured), by Newton-Euler at q̈ = 0 with the model's own inertias (the regressor's sum, Y unformed).
inline void master_dynamics_cancellation(const RobotModel& model, RobotData& data, double w, VecN& tau_m) {
  update_bias(model, data);
  for (int i = 0; i < data.n; ++i)
    tau_m[i] += w * (data.bias[i] + model.joints[static_cast<size_t>(i)].damping * data.dq[i]);
}

// (n̂, w_h, F_v, w, T; Δp) => (F_h,n = n̂ n̂ᵀ F_h; Δp_v += T w (F_v − F_h,n), Δp_h += T w (F_h,n − F_v))
// (3.17)-(3.19): the hand's force along the normal and the two momentum errors.
inline void rigid_force_errors(const Eigen::Vector3d& normal, const Wrench& wrench_h, const Eigen::Vector3d& force_v,
                               double w, double T, Eigen::Vector3d& force_h_normal, ForceErrorIntegrals& integrals) {
  const Eigen::Vector3d f_h = wrench_h.head<3>();
  force_h_normal = normal * normal.dot(f_h);
  integrals.momentum_v += T * w * (force_v - force_h_normal);
  integrals.momentum_h += T * w * (force_h_normal - force_v);
}

// (J_v, J_m, F_h,n, F_v, Δp, K_fv, K_fm, w; τ) => (τ_v += w J_vᵀ(F_h,n − K_fv Δp_v), τ_m −= w J_mᵀ(F_v − K_fm Δp_h))
// the force terms of (3.21) and (3.20).
inline void rigid_force_torques(const Mat6N& J_v, const Mat6N& J_m, const Eigen::Vector3d& force_h_normal,
                                const Eigen::Vector3d& force_v, const ForceErrorIntegrals& integrals, double Kf_v,
                                double Kf_m, double w, VecN& tau_v, VecN& tau_m) {
  tau_v += w * (J_v.topRows<3>().transpose() * (force_h_normal - Kf_v * integrals.momentum_v));
  tau_m -= w * (J_m.topRows<3>().transpose() * (force_v - Kf_m * integrals.momentum_h));
}

// Storage of operator_multiplier, kept by the caller from tick to tick.
struct OperatorMultiplierScratch {
  MatKK aat;  // A Aᵀ
  SmallCholesky<kMaxConstraints> aat_factor;
};

// (A, J_m, w_h) => (λ_m = (A Aᵀ)⁻¹ A J_mᵀ w_h)   (3.24), the hand's push along the constraints, with
// τ_h = J_mᵀ w_h (2.23): the simulation senses all six components, where the thesis estimated them
// from the master's model (2.20).
inline void operator_multiplier(const MatKN& A, const Mat6N& J_m, const Wrench& wrench_h,
                                OperatorMultiplierScratch& scratch, VecK& lambda_m) {
  scratch.aat.noalias() = A * A.transpose();
  scratch.aat_factor.compute(scratch.aat);
  const VecN tau_hand = J_m.transpose() * wrench_h;
  lambda_m.noalias() = A * tau_hand;
  scratch.aat_factor.solveInPlace(lambda_m);
}

// (λ_m, λ_v, w, T; E) => (E += T w (λ_m + λ_v))   (3.26), the multipliers' force error.
inline void tissue_force_error(const VecK& lambda_m, const VecK& lambda_v, double w, double T,
                               ForceErrorIntegrals& integrals) {
  integrals.lambda += T * w * (lambda_m + lambda_v);
}

// (A, λ_m, λ_v, E, K_fv, K_fm, w; τ) => (τ_v += w Aᵀ(λ_m + K_fv E), τ_m += w Aᵀ(λ_v + K_fm E))
// the force terms of (3.28) and (3.27).
inline void tissue_force_torques(const MatKN& A, const VecK& lambda_m, const VecK& lambda_v,
                                 const ForceErrorIntegrals& integrals, double Kf_v, double Kf_m, double w, VecN& tau_v,
                                 VecN& tau_m) {
  tau_v += w * (A.transpose() * (lambda_m + Kf_v * integrals.lambda));
  tau_m += w * (A.transpose() * (lambda_v + Kf_m * integrals.lambda));
}

}  // namespace needle::haptics
