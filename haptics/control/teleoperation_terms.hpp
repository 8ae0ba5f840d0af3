// The teleoperation controller (thesis 3.2) one equation group at a time: Teleoperation::step
// calls these in order. Each states what it reads and what it writes; signs and forms are the
// corrected ones of docs/CONTROLLER.md, which maps every equation to its function and test.
// Functions named *_torques add their terms to τ (already holding the free-motion part).
// All allocation-free.
#pragma once

#include "haptics/control/gains.hpp"
#include "haptics/control/virtual_world.hpp"

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
bool advance_contact_blend(ContactMode mode, double rate, ContactBlend& blend);

// (sensed w_h, cutoff, T; filtered) => (filtered)   first-order low-pass of the wrench entering
// the force terms (not in the thesis: docs/CONTROLLER.md, sensed-wrench filter).
void filter_wrench(const Wrench& sensed, double cutoff_Hz, double T, Wrench& filtered);

// (K_am, K_pm, q̇_m, s_am) => (τ_m = −K_am q̇_m − K_pm s_am)   (3.13), as printed.
void master_free_motion_torque(const RobotGains& g, const VecN& dq, const VecN& s_a, VecN& tau);

// (K_av, K_pv, sign, q̇_v, s_av) => (τ_v0, B), τ_v = τ_v0 − B q̇_v = −K_av q̇_v − K_pv s_av   (3.14),
// dissipative sign (AsPrinted flips it). Split so the virtual world applies −B q̇_v implicitly.
void virtual_free_motion_torque(const RobotGains& g, VirtualFeedback feedback, const VecN& dq, const VecN& s_a,
                                VecN& tau0, VecN& velocity_gain);

// (master model, data after update_frames) => (Y_m(q_m, q̇_m, 0) θ_m = C_m q̇_m + D_m q̇_m + g_m)
// the dynamic cancellation of (3.20), (3.27), without H_m q̈_m: q̈_m is not measured.
void master_dynamics_cancellation(const RobotModel& model, RobotData& data, VecN& y_theta);

// (n̂, w_h, F_v, w, T; Δp) => (F_h,n = n̂ n̂ᵀ F_h; Δp_v += T w (F_v − F_h,n), Δp_h += T w (F_h,n − F_v))
// (3.17)-(3.19): the hand's force along the normal and the two momentum errors.
void rigid_force_errors(const Eigen::Vector3d& normal, const Wrench& wrench_h, const Eigen::Vector3d& force_v, double w,
                        double T, Eigen::Vector3d& force_h_normal, ForceErrorIntegrals& integrals);

// (J_v, J_m, F_h,n, F_v, Δp, K_fv, K_fm, w) => (τ_v += w J_vᵀ(F_h,n − K_fv Δp_v), τ_m −= w J_mᵀ(F_v − K_fm Δp_h))
// the force terms of (3.21) and (3.20).
void rigid_force_torques(const Mat6N& J_v, const Mat6N& J_m, const Eigen::Vector3d& force_h_normal,
                         const Eigen::Vector3d& force_v, const ForceErrorIntegrals& integrals, double Kf_v, double Kf_m,
                         double w, VecN& tau_v, VecN& tau_m);

// (A, J_m, w_h) => (λ_m = (A Aᵀ)⁻¹ A J_mᵀ w_h)   (3.24), the hand's push along the constraints.
void operator_multiplier(const MatKN& A, const Mat6N& J_m, const Wrench& wrench_h, VecK& lambda_m);

// (λ_m, λ_v, w, T; E) => (E += T w (λ_m + λ_v))   (3.26), the multipliers' force error.
void tissue_force_error(const VecK& lambda_m, const VecK& lambda_v, double w, double T, ForceErrorIntegrals& integrals);

// (A, λ_m, λ_v, E, K_fv, K_fm, w) => (τ_v += w Aᵀ(λ_m + K_fv E), τ_m += w Aᵀ(λ_v + K_fm E))
// the force terms of (3.28) and (3.27).
void tissue_force_torques(const MatKN& A, const VecK& lambda_m, const VecK& lambda_v,
                          const ForceErrorIntegrals& integrals, double Kf_v, double Kf_m, double w, VecN& tau_v,
                          VecN& tau_m);

}  // namespace needle::haptics
