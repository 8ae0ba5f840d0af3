#include "haptics/constraints/nonholonomic_multiplier.hpp"

#include "haptics/model/dynamics.hpp"

namespace needle::haptics {

void NonholonomicMultiplier::reset(int k) { psi_integral_.setZero(k); }

// [[gnu::flatten]]: per-tick code, Eigen calls inlined (see kinematics.cpp).
[[gnu::flatten]] void NonholonomicMultiplier::solve(const RobotModel& model, RobotData& data, const MatKN& A,
                                                    const MatKN& A_dot, const VecN& tau, VecK& lambda, VecN& ddq) {
  const int k = static_cast<int>(A.rows());
  if (psi_integral_.size() != k) reset(k);
  forward_dynamics(model, data, tau, ddq);  // ddq = H⁻¹(τ − C q̇ − D q̇ − g); H factorized
  // H⁻¹Aᵀ column by column (kept transposed so the storage has a fixed maximum).
  hinv_at_ = A;
  for (int r = 0; r < k; ++r) {
    VecN col = A.row(r).transpose();
    data.llt.solveInPlace(col);
    hinv_at_.row(r) = col.transpose();
  }
  schur_.noalias() = A * hinv_at_.transpose();  // A H⁻¹ Aᵀ
  const VecK psi = A * data.dq;
  const VecK psi_dot_target = -2.0 * gains_.alpha * psi - gains_.beta * psi_integral_;  // (3.23)
  lambda = psi_dot_target - A_dot * data.dq - A * ddq;                                  // (3.22) bracket
  schur_factor_.compute(schur_);
  schur_factor_.solveInPlace(lambda);
  ddq.noalias() += hinv_at_.transpose() * lambda;
}

void NonholonomicMultiplier::response(RobotData& data, const VecN& f, VecN& m, VecK& l) const {
  m = f;
  data.llt.solveInPlace(m);       // H⁻¹ f
  l.noalias() = -(hinv_at_ * f);  // −A H⁻¹ f (H symmetric: row r of hinv_at_ is (H⁻¹ a_r)ᵀ)
  schur_factor_.solveInPlace(l);
  m.noalias() += hinv_at_.transpose() * l;
}

void NonholonomicMultiplier::advance(const MatKN& A, const VecN& dq, double h) {
  if (psi_integral_.size() != A.rows()) reset(static_cast<int>(A.rows()));
  psi_integral_ += h * (A * dq);
}

}  // namespace needle::haptics
