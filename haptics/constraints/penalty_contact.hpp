// Rigid contact by the Generic Penalty Method (thesis 3.2.1, after Bayo and Avello; Gutiérrez-Giles
// and Arteaga-Pérez 2017). λ = α(φ̈ + 2ξω φ̇ + ω² φ) (3.15) and F_v = J_φᵀ λ (3.16): F_v is the
// force the tool exerts on the surface, so λ < 0 while pressing, and the surface acts on the
// robot with −J_φᵀλ (the penalty term of Bayo's H q̈ + … + J_φᵀλ = τ). λ is clamped to ≤ 0:
// a surface can push, not pull.
#pragma once

#include "haptics/constraints/implicit_surface.hpp"
#include "haptics/model/robot_data.hpp"

namespace needle::haptics {

struct GpmParams {
  double alpha = 0.02;  // kg (thesis 4.3)
  double xi = 100.0;    // damping ratio (thesis 4.3)
  double omega = 200.0; // rad/s (thesis 4.3)
  double stiffness() const { return alpha * omega * omega; }  // N/m, since φ is in metres
  double damping() const { return 2.0 * alpha * xi * omega; } // N·s/m
};

// (3.15) as printed, from a known φ̈.
double gpm_multiplier(const GpmParams& p, const SurfaceMotion& m);
// (3.16) with the unit gradient.
Eigen::Vector3d gpm_force(const SurfaceSample& s, double lambda);

// Acceleration and λ of a robot whose tip is held by the penalty, solved together (φ̈ depends on
// q̈): (H + α' J_φᵀJ_φ) q̈ = τ − C q̇ − D q̇ − g − J_φᵀ α γ. With step > 0 the damping and
// stiffness terms are taken at the end of a semi-implicit Euler step of that length
// (φ̇ → φ̇ + h φ̈, φ → φ + h φ̇ + h² φ̈), which keeps the stiff penalty stable at any step;
// step = 0 is (3.15) in continuous time. Needs the kinematics (J, J̇) and H, bias at the state.
struct PenaltyResult {
  double lambda = 0.0;
  bool active = false;  // false: φ > 0 or λ would pull; q̈ is then the free acceleration
};
PenaltyResult penalty_acceleration(const GpmParams& p, const RobotModel& model, RobotData& data,
                                   const SurfaceSample& surface, const VecN& tau, double step, VecN& ddq);

}  // namespace needle::haptics
