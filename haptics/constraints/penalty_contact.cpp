#include "haptics/constraints/penalty_contact.hpp"

#include "haptics/model/dynamics.hpp"

namespace needle::haptics {

double gpm_multiplier(const GpmParams& p, const SurfaceMotion& m, double step) {
  const double c = 2.0 * p.xi * p.omega, k = p.omega * p.omega, h = step;
  return p.alpha * (m.phi_ddot * (1.0 + c * h + k * h * h) + c * m.phi_dot + k * (m.phi + h * m.phi_dot));
}

Eigen::Vector3d gpm_force(const SurfaceSample& s, double lambda) { return s.gradient * lambda; }

PenaltyResult penalty_acceleration(const GpmParams& p, const RobotModel& model, RobotData& data,
                                   const SurfaceSample& surface, const VecN& tau, double step, VecN& ddq) {
  forward_dynamics(model, data, tau, ddq);  // also factorizes H
  if (surface.phi > 0.0) return {};
  const Eigen::Vector3d v = data.tip_twist.head<3>();
  // J_φ = n̂ᵀ J_lin (1×n); φ̈ = J_φ q̈ + γ0 with γ0 = n̂ᵀ J̇_lin q̇ + ẋᵀ∇²φ ẋ.
  Eigen::Matrix<double, 1, Eigen::Dynamic, Eigen::RowMajor, 1, kMaxDof> j_phi = surface.gradient.transpose() * data.J.topRows<3>();
  const double phi_dot = surface.gradient.dot(v);
  const double gamma0 = surface.gradient.dot(data.Jdot.topRows<3>() * data.dq) +
                        v.dot(surface.hessian * v);
  // λ is affine in φ̈: λ = a_eff J_φ q̈ + rest, with a_eff = ∂λ/∂φ̈ and rest = λ at J_φ q̈ = 0.
  const double a_eff = gpm_multiplier(p, {0.0, 0.0, 1.0}, step);
  const double rest = gpm_multiplier(p, {surface.phi, phi_dot, gamma0}, step);
  // With H q̈ = f − J_φᵀλ, eliminate q̈ (Sherman-Morrison on the rank-1 term):
  // q̈ = q̈_free − H⁻¹J_φᵀ λ  ⇒  λ = (a_eff J_φ q̈_free + rest) / (1 + a_eff J_φ H⁻¹ J_φᵀ).
  VecN hinv_jt = j_phi.transpose();
  data.llt.solveInPlace(hinv_jt);
  const double lambda = (a_eff * j_phi.dot(ddq) + rest) / (1.0 + a_eff * j_phi.dot(hinv_jt));
  if (lambda >= 0.0) return {};
  ddq -= hinv_jt * lambda;
  return {lambda, true};
}

}  // namespace needle::haptics
