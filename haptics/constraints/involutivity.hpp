// Frobenius check of a Pfaffian constraint A(q) q̇ = 0 (thesis 3.1.1, Proposition 2.1): the
// distribution Δ = ker A is involutive iff every Lie bracket of fields in Δ stays in Δ. For
// g_i, g_j ∈ ker A, A [g_i, g_j] = (D_{g_j}A) g_i − (D_{g_i}A) g_j, which needs only directional
// derivatives of A (central differences here), not a smooth basis of Δ. Analysis code, allocates.
#pragma once

#include <Eigen/Core>
#include <functional>

namespace needle::haptics {

using PfaffianField = std::function<Eigen::MatrixXd(const Eigen::VectorXd& q)>;

// max over pairs of an orthonormal basis of ker A(q) of |A [g_i, g_j]|: 0 for an involutive
// (integrable, holonomic) distribution, > 0 where it is not.
double involutivity_defect(const PfaffianField& A, const Eigen::VectorXd& q, double eps = 1e-6);

}  // namespace needle::haptics
