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
  double alpha = 0.02;                                         // kg (thesis 4.3)
  double xi = 100.0;                                           // damping ratio (thesis 4.3)
  double omega = 200.0;                                        // rad/s (thesis 4.3)
  double stiffness() const { return alpha * omega * omega; }   // N/m, since φ is in metres
  double damping() const { return 2.0 * alpha * xi * omega; }  // N·s/m
};

// (α, ξ, ω; φ, φ̇, φ̈; h) => (λ)   (3.15), damping and stiffness at the end of a step of length h:
// λ = α(φ̈ + 2ξω (φ̇ + h φ̈) + ω² (φ + h φ̇ + h² φ̈)), the semi-implicit Euler form that keeps the
// stiff penalty stable at any step (docs/CONTROLLER.md). h = 0 is (3.15) as printed; the servo
// passes its sub-step. λ is affine in φ̈.
double gpm_multiplier(const GpmParams& p, const SurfaceMotion& m, double step);
// (n̂, λ) => (F_v = J_φᵀ λ = n̂ λ)   (3.16), with the unit gradient.
Eigen::Vector3d gpm_force(const SurfaceSample& s, double lambda);

struct PenaltyResult {
  double lambda = 0.0;
  bool active = false;  // false: φ > 0 or λ would pull; q̈ is then the free acceleration
};
// (model, data with J, J̇, H and bias; surface, τ, h) => (q̈, λ)   (2.21) with (3.15): the robot
// whose tip the penalty holds, λ = gpm_multiplier(…, h) solved together with the dynamics (φ̈
// depends on q̈): (H + α' J_φᵀJ_φ) q̈ = τ − C q̇ − D q̇ − g − J_φᵀ α γ.
PenaltyResult penalty_acceleration(const GpmParams& p, const RobotModel& model, RobotData& data,
                                   const SurfaceSample& surface, const VecN& tau, double step, VecN& ddq);

using RowN = Eigen::Matrix<double, 1, Eigen::Dynamic, Eigen::RowMajor, 1, kMaxDof>;
// (data with J, surface) => J_φ = n̂ᵀ J_lin, the rate of φ per joint rate.
RowN surface_jacobian(const RobotData& data, const SurfaceSample& surface);
// (α, ξ, ω; data with J, J̇ and q̇; surface, J_φ, m = ∂q̈/∂(−λ) = M J_φᵀ, h; q̈ without the penalty)
// => (λ; q̈ −= m λ)   (3.15) solved with dynamics whose response to a joint torque f is q̈ += M f:
// λ = (α' J_φ q̈ + λ₀) / (1 + α' J_φ m), α' = ∂λ/∂φ̈, λ₀ = λ at J_φ q̈ = 0 (Sherman-Morrison on the
// rank-one term). M = H⁻¹ for the free robot (penalty_acceleration); inside tissue it is the
// nonholonomic constraint's (NonholonomicMultiplier::response). Inactive (q̈ untouched) when λ ≥ 0.
PenaltyResult penalty_response(const GpmParams& p, const RobotData& data, const SurfaceSample& surface,
                               const RowN& j_phi, const VecN& mobility, double step, VecN& ddq);

}  // namespace needle::haptics
