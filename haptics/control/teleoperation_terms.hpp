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

// How far each contact's terms are on (not in the thesis: docs/CONTROLLER.md, blending).
struct ContactBlend {
  double rigid = 0.0;   // (3.17)-(3.21)
  double tissue = 0.0;  // (3.24)-(3.28)
  double axial = 0.0;   // the tissue along the needle
  double any() const { return std::max({rigid, tissue, axial}); }
};

// The integrals of the force errors, each restarted at a new contact of its kind.
struct ForceErrorIntegrals {
  Eigen::Vector3d momentum_h = Eigen::Vector3d::Zero();  // Δp_h (3.19)
  Eigen::Vector3d momentum_v = Eigen::Vector3d::Zero();  // Δp_v (3.19)
  VecK lambda = VecK::Zero(2);                           // E = ∫(λ_m + λ_v) dt (3.26)
};

// (which contacts hold, T / switch time; blend, integrals) => (blend, integrals)   contact
// blending: each weight ramps toward 1 while its contact holds and toward 0 after it; a contact is
// new when it holds while its weight is 0, and its force integrals restart then.
inline void advance_contact_blend(bool rigid, bool tissue, bool axial, double rate, ContactBlend& blend,
                                  ForceErrorIntegrals& integrals) {
  auto ramp = [rate](bool holds, double& w) {
    const bool starts = holds && w == 0.0;
    w = std::clamp(w + (holds ? rate : -rate), 0.0, 1.0);
    return starts;
  };
  if (ramp(rigid, blend.rigid)) integrals.momentum_h.setZero(), integrals.momentum_v.setZero();
  if (ramp(tissue, blend.tissue)) integrals.lambda.setZero();
  ramp(axial, blend.axial);
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

// (master model, data after update_frames, w, gravity in every mode; τ_m) => (τ_m += w Y_m(q_m, q̇_m, 0) θ_m,
// or with the gravity always: τ_m += g_m + w (Y_m(q_m, q̇_m, 0) θ_m − g_m))   the dynamic cancellation of
// (3.20), (3.27): Y θ = C_m q̇_m + D_m q̇_m + g_m, without H_m q̈_m (q̈_m is not measured), by Newton-Euler
// at q̈ = 0 with the model's own inertias (the regressor's sum, Y unformed). The tool law keeps its
// gravity part on in free motion too (docs/CONTROLLER.md, "The tool").
inline void master_dynamics_cancellation(const RobotModel& model, RobotData& data, double w, bool gravity_always,
                                         VecN& tau_m) {
  if (gravity_always) {
    update_gravity(model, data);
    tau_m += (1.0 - w) * data.g;
  }
  if (w == 0.0) return;
  update_bias(model, data);
  for (int i = 0; i < data.n; ++i)
    tau_m[i] += w * (data.bias[i] + model.joints[static_cast<size_t>(i)].damping * data.dq[i]);
}

// (m, g, J_m, w_h; τ_m) => (τ_m += J_mᵀ [m g; 0]; w_net = w_h + [m g; 0])   the tool's weight (not in the
// thesis: docs/CONTROLLER.md, "The tool"): the device presses the stylus down with it, and the force
// terms take what the hand does to the tool beyond carrying it.
inline void tool_weight(double mass, const Eigen::Vector3d& gravity, const Mat6N& J_m, const Wrench& wrench_h,
                        VecN& tau_m, Wrench& wrench_net) {
  const Eigen::Vector3d weight = mass * gravity;
  tau_m.noalias() += J_m.topRows<3>().transpose() * weight;
  wrench_net = wrench_h;
  wrench_net.head<3>() += weight;
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

// (J_v, J_m, F_h,n, F_v, Δp, K_fv, K_fm, s, w; τ) => (τ_v += w J_vᵀ(F_h,n − K_fv Δp_v), τ_m −= w s J_mᵀ(F_v − K_fm
// Δp_h)) the force terms of (3.21) and (3.20), forces in the scene's newtons, s the force scale (hand per scene).
inline void rigid_force_torques(const Mat6N& J_v, const Mat6N& J_m, const Eigen::Vector3d& force_h_normal,
                                const Eigen::Vector3d& force_v, const ForceErrorIntegrals& integrals, double Kf_v,
                                double Kf_m, double scale, double w, VecN& tau_v, VecN& tau_m) {
  tau_v += w * (J_v.topRows<3>().transpose() * (force_h_normal - Kf_v * integrals.momentum_v));
  tau_m -= (w * scale) * (J_m.topRows<3>().transpose() * (force_v - Kf_m * integrals.momentum_h));
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

// (A, λ_m, E, K_fv, w; τ_v) => (τ_v += w Aᵀ(λ_m + K_fv E))   the force term of (3.28), the hand's
// push along the constraints driving the virtual needle; multipliers in the scene's newtons.
inline void tissue_force_torque_virtual(const MatKN& A, const VecK& lambda_m, const ForceErrorIntegrals& integrals,
                                        double Kf_v, double w, VecN& tau_v) {
  tau_v += w * (A.transpose() * (lambda_m + Kf_v * integrals.lambda));
}

// (A, λ_v, E, K_fm, s, w; τ_m) => (τ_m += w s Aᵀ(λ_v + K_fm E))   the force term of (3.27), the
// constraint's multipliers reflected to the master (thesis law); s the force scale (hand per scene).
inline void tissue_force_torque_master(const MatKN& A, const VecK& lambda_v, const ForceErrorIntegrals& integrals,
                                       double Kf_m, double scale, double w, VecN& tau_m) {
  tau_m += (w * scale) * (A.transpose() * (lambda_v + Kf_m * integrals.lambda));
}

// (needle frame [x₅ y₅ z₅] of the virtual tip, J_m, q̇_m, b, w; τ_m) => (τ_m −= w b J_mᵀ P ẋ_m,
// P = y₅y₅ᵀ + z₅z₅ᵀ)   the master's sideways motion damped while the needle is in tissue, where
// the virtual needle cannot move sideways (not in the thesis: docs/CONTROLLER.md, "No wobble"):
// a damper b on the master tip's velocity across the needle, dissipative by construction.
inline void lateral_damping_torque(const Eigen::Matrix3d& needle_frame, const Mat6N& J_m, const VecN& dq_m, double b,
                                   double w, VecN& tau_m) {
  const Eigen::Vector3d v = J_m.topRows<3>() * dq_m;
  const Eigen::Vector3d y = needle_frame.col(1), z = needle_frame.col(2);
  const Eigen::Vector3d force = -(w * b) * (y * y.dot(v) + z * z.dot(v));
  tau_m.noalias() += J_m.topRows<3>().transpose() * force;
}

// (needle frame [x₅ y₅ z₅] of the virtual tip, x_m, x_v) => (P (x_m − x_v), P = y₅y₅ᵀ + z₅z₅ᵀ)   the
// master tip's offset across the virtual needle's line.
inline Eigen::Vector3d lateral_offset(const Eigen::Matrix3d& needle_frame, const Eigen::Vector3d& x_m,
                                      const Eigen::Vector3d& x_v) {
  const Eigen::Vector3d d = x_m - x_v;
  const Eigen::Vector3d y = needle_frame.col(1), z = needle_frame.col(2);
  return y * y.dot(d) + z * z.dot(d);
}

// (needle frame of the virtual tip, x_m, x_v, J_m, K, w; τ_m) => (τ_m −= w K J_mᵀ P (x_m − x_v))   the
// master tip held to the virtual needle's line while the needle is in tissue, in place of (3.27)'s
// reflection (tool law, not in the thesis: docs/CONTROLLER.md, "Passivity at the hand"). The
// constraint holds the virtual tip still across the needle, so this is a spring to a line pivoting
// about a still point, storing ½ w K |P (x_m − x_v)|².
inline void lateral_spring_torque(const Eigen::Matrix3d& needle_frame, const Eigen::Vector3d& x_m,
                                  const Eigen::Vector3d& x_v, const Mat6N& J_m, double K, double w, VecN& tau_m) {
  const Eigen::Vector3d force = -(w * K) * lateral_offset(needle_frame, x_m, x_v);
  tau_m.noalias() += J_m.topRows<3>().transpose() * force;
}

// (x₅, J_m, q̇_m, b, w; τ_m) => (τ_m −= w b J_mᵀ x₅x₅ᵀ ẋ_m)   the master's motion along the needle
// damped while the tissue's axial force acts (not in the thesis: docs/CONTROLLER.md, "The tissue
// along the needle"); dissipative by construction.
inline void axial_damping_torque(const Eigen::Vector3d& axis, const Mat6N& J_m, const VecN& dq_m, double b, double w,
                                 VecN& tau_m) {
  const double v = axis.dot(J_m.topRows<3>() * dq_m);
  tau_m.noalias() -= (w * b * v) * (J_m.topRows<3>().transpose() * axis);
}

// (x₅, f_h in the scene's newtons, F_t, J_v, J_m, s, w; τ) => (F_h,a = x₅ᵀ f_h; τ_v += w J_vᵀ x₅ F_h,a,
// τ_m −= w s J_mᵀ x₅ F_t)   the tissue along the needle (not in the thesis: docs/CONTROLLER.md, "The
// tissue along the needle"): (3.21) and (3.20)'s force terms with n̂ = x₅ and F_v = F_t x₅, F_t the
// tissue's axial force (needle on tissue), without their integrals. Returns F_h,a.
inline double axial_force_torques(const Eigen::Vector3d& axis, const Wrench& wrench_h, double axial_force,
                                  const Mat6N& J_v, const Mat6N& J_m, double scale, double w, VecN& tau_v,
                                  VecN& tau_m) {
  const double push = axis.dot(wrench_h.head<3>());
  tau_v.noalias() += (w * push) * (J_v.topRows<3>().transpose() * axis);
  tau_m.noalias() -= (w * scale * axial_force) * (J_m.topRows<3>().transpose() * axis);
  return push;
}

// Scratch of axial_spring_stiffness, kept by the caller so the tick allocates nothing.
struct AxialSpringScratch {
  MatN m;
  VecN v, w;
  SmallCholesky<kMaxDof> llt;
};

// (K, H_v, B, h, J_v, x₅, T) => min(K, 2 / (T² x₅ᵀ J_v (H_v + h B)⁻¹ J_vᵀ x₅))   the spring along the
// needle held at half the explicit limit of the virtual tip's mass along it: the spring acts on the
// virtual robot once per tick T, and a spring K on a mass m held for T is stable for K T² / m < 4
// (docs/CONTROLLER.md, "The needle along the hand"). H_v + h B is the matrix the virtual world's
// semi-implicit sub-step h solves with; the mass along x₅ without the needle's constraint is the
// smaller one, so the bound holds with it.
inline double axial_spring_stiffness(double K, const MatN& H_v, const VecN& B, double h, const Mat6N& J_v,
                                     const Eigen::Vector3d& axis, double T, AxialSpringScratch& scratch) {
  scratch.m = H_v;
  scratch.m.diagonal() += h * B;
  scratch.llt.compute(scratch.m);
  scratch.v.noalias() = J_v.topRows<3>().transpose() * axis;
  scratch.w = scratch.v;
  scratch.llt.solveInPlace(scratch.w);
  const double inverse_mass = scratch.v.dot(scratch.w);
  if (!(inverse_mass > 0.0)) return K;  // the tip cannot move along x₅: nothing to bound
  return std::min(K, 2.0 / (T * T * inverse_mass));
}

// (x₅, x_m, x_v, J_v, J_m, K, s, w; τ) => (F = w K x₅ᵀ(x_m − x_v); τ_v += J_vᵀ x₅ F, τ_m −= s J_mᵀ x₅ F)
// the needle along the hand (tool law, not in the thesis: docs/CONTROLLER.md, "The needle along the
// hand"): a spring along the needle between the master tip and the virtual tip in place of
// axial_force_torques' force-force channel, storing ½ w K (x₅ᵀ(x_m − x_v))². The virtual needle follows
// the hand's position, so when a membrane gives way it runs ahead by the spring's stretch F/K, not
// by as far as the hand's push carries it unresisted. Returns F, scene newtons.
inline double axial_spring_torques(const Eigen::Vector3d& axis, const Eigen::Vector3d& x_m, const Eigen::Vector3d& x_v,
                                   const Mat6N& J_v, const Mat6N& J_m, double K, double scale, double w, VecN& tau_v,
                                   VecN& tau_m) {
  const double force = w * K * axis.dot(x_m - x_v);
  tau_v.noalias() += force * (J_v.topRows<3>().transpose() * axis);
  tau_m.noalias() -= (scale * force) * (J_m.topRows<3>().transpose() * axis);
  return force;
}

}  // namespace needle::haptics
