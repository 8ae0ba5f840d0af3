#include "haptics/constraints/involutivity.hpp"

#include <Eigen/SVD>

namespace needle::haptics {

double involutivity_defect(const PfaffianField& A, const Eigen::VectorXd& q, double eps) {
  const Eigen::MatrixXd a = A(q);
  Eigen::JacobiSVD<Eigen::MatrixXd> svd(a, Eigen::ComputeFullV);
  const Eigen::Index rank = svd.rank();
  const Eigen::MatrixXd kernel = svd.matrixV().rightCols(q.size() - rank);
  auto directional = [&](const Eigen::VectorXd& v) {
    return Eigen::MatrixXd((A(q + eps * v) - A(q - eps * v)) / (2 * eps));
  };
  double worst = 0.0;
  for (Eigen::Index i = 0; i < kernel.cols(); ++i)
    for (Eigen::Index j = i + 1; j < kernel.cols(); ++j) {
      const Eigen::VectorXd gi = kernel.col(i), gj = kernel.col(j);
      worst = std::max(worst, (directional(gj) * gi - directional(gi) * gj).norm());
    }
  return worst;
}

}  // namespace needle::haptics
