// Cholesky factorization A = L Lᵀ of a small symmetric positive definite matrix (n ≤ kMax), in
// plain loops over fixed storage. At the sizes of these robots (n ≤ 6, and k ≤ 6 constraints)
// Eigen's dynamic-size LLT/LDLT spend most of their time in general-purpose kernels; this is a
// drop-in for the servo tick (compute, solveInPlace), allocation-free.
#pragma once

#include <Eigen/Core>
#include <algorithm>
#include <cmath>

namespace needle::haptics {

template <int kMax>
class SmallCholesky {
 public:
  // Factorizes the lower triangle of the square matrix `a`. A pivot that is not positive (beyond
  // round-off of the diagonal) makes ok() false; its direction is then dropped from the solution
  // (set to zero, as Eigen's LDLT does) instead of filling it with NaN: a singular constraint
  // Gram matrix at a singular pose yields finite multipliers.
  template <typename Derived>
  bool compute(const Eigen::MatrixBase<Derived>& a) {
    n_ = static_cast<int>(a.rows());
    ok_ = true;
    double scale = 0.0;
    for (int j = 0; j < n_; ++j) scale = std::max(scale, std::abs(a(j, j)));
    for (int j = 0; j < n_; ++j) {
      double d = a(j, j);
      for (int k = 0; k < j; ++k) d -= l_[j][k] * l_[j][k];
      const bool positive = d > 1e-14 * scale;
      ok_ = ok_ && positive;
      l_[j][j] = positive ? std::sqrt(d) : 0.0;
      inv_diag_[j] = positive ? 1.0 / l_[j][j] : 0.0;
      for (int i = j + 1; i < n_; ++i) {
        double s = a(i, j);
        for (int k = 0; k < j; ++k) s -= l_[i][k] * l_[j][k];
        l_[i][j] = s * inv_diag_[j];
      }
    }
    return ok_;
  }
  bool ok() const { return ok_; }

  // x ← A⁻¹ x for each column of x (forward then backward substitution).
  template <typename Derived>
  void solveInPlace(Eigen::MatrixBase<Derived>& x) const {
    for (Eigen::Index c = 0; c < x.cols(); ++c) {
      for (int i = 0; i < n_; ++i) {
        double s = x(i, c);
        for (int k = 0; k < i; ++k) s -= l_[i][k] * x(k, c);
        x(i, c) = s * inv_diag_[i];
      }
      for (int i = n_ - 1; i >= 0; --i) {
        double s = x(i, c);
        for (int k = i + 1; k < n_; ++k) s -= l_[k][i] * x(k, c);
        x(i, c) = s * inv_diag_[i];
      }
    }
  }

 private:
  int n_ = 0;
  bool ok_ = false;
  double l_[kMax][kMax] = {};
  double inv_diag_[kMax] = {};
};

}  // namespace needle::haptics
