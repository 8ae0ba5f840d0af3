// Lagrange multipliers of k nonholonomic constraints A(q) q̇ = 0 acting as H q̈ + C q̇ + D q̇ + g =
// τ + Aᵀλ (2.33). λ (3.22) makes the residual ψ = A q̇ obey ψ̇ + 2α ψ + β ∫ψ = 0 (3.23), a
// stable second-order decay instead of the drifting ψ̇ = 0 (Murray et al.'s solution).
#pragma once

#include "haptics/constraints/pfaffian.hpp"
#include "haptics/model/small_cholesky.hpp"

namespace needle::haptics {

struct NonholonomicGains {
  double alpha = 50.0;   // 1/s; the thesis leaves α_v, β_v unspecified ("fast convergence")
  double beta = 2500.0;  // 1/s²; β = α² makes (3.23) critically damped
};

class NonholonomicMultiplier {
 public:
  explicit NonholonomicMultiplier(NonholonomicGains gains = {}) : gains_(gains) {}

  // Restarts ∫ψ (at contact onset, t₀ of (3.23)) for k constraints.
  void reset(int k);
  const VecK& psi_integral() const { return psi_integral_; }
  const NonholonomicGains& gains() const { return gains_; }

  // λ (3.22) at the state of `data` (H and bias up to date), for the applied torque τ; writes q̈
  // of the constrained dynamics. Allocation-free.
  void solve(const RobotModel& model, RobotData& data, const MatKN& A, const MatKN& A_dot, const VecN& tau,
             VecK& lambda, VecN& ddq);
  // After solve, with the same data: how an extra joint torque f changes the solution: q̈ += m,
  // λ += l, with m = M f, M = H⁻¹ − H⁻¹Aᵀ(AH⁻¹Aᵀ)⁻¹AH⁻¹ (what the constraint lets f move) and
  // l = −(AH⁻¹Aᵀ)⁻¹AH⁻¹ f (the multipliers that keep (3.23) with f applied).
  void response(RobotData& data, const VecN& f, VecN& m, VecK& l) const;
  // ∫ψ += ψ h, after a step of length h.
  void advance(const MatKN& A, const VecN& dq, double h);

 private:
  NonholonomicGains gains_;
  VecK psi_integral_;
  MatKN hinv_at_;                                // H⁻¹Aᵀ, stored as (H⁻¹Aᵀ)ᵀ rows
  MatKK schur_;                                  // A H⁻¹ Aᵀ
  SmallCholesky<kMaxConstraints> schur_factor_;  // of A H⁻¹ Aᵀ
};

}  // namespace needle::haptics
