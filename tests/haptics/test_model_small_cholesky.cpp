// The loop Cholesky of the servo tick against Eigen's LLT, and its behaviour on a singular matrix.
#include <gtest/gtest.h>

#include <Eigen/Cholesky>
#include <random>

#include "haptics/model/small_cholesky.hpp"
#include "haptics/model/types.hpp"

using namespace needle::haptics;

TEST(SmallCholesky, SolvesLikeEigensLltOnRandomSpdMatrices) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int n = 1; n <= kMaxDof; ++n) {
    for (int trial = 0; trial < 20; ++trial) {
      Eigen::MatrixXd m(n, n);
      for (double& v : m.reshaped()) v = u(rng);
      const Eigen::MatrixXd a = m * m.transpose() + 0.1 * Eigen::MatrixXd::Identity(n, n);
      Eigen::MatrixXd b(n, 3);
      for (double& v : b.reshaped()) v = u(rng);
      SmallCholesky<kMaxDof> chol;
      ASSERT_TRUE(chol.compute(a));
      Eigen::MatrixXd x = b;
      chol.solveInPlace(x);
      const Eigen::MatrixXd expected = a.llt().solve(b);
      EXPECT_LT((x - expected).norm(), 1e-11 * (1.0 + expected.norm())) << "n = " << n;
      EXPECT_LT((a * x - b).norm(), 1e-11 * (1.0 + b.norm())) << "n = " << n;
    }
  }
}

TEST(SmallCholesky, SingularMatrixIsReportedAndGivesAFiniteSolution) {
  // Rank 1: the second pivot is zero up to round-off; that direction is dropped, not divided by.
  const Eigen::Vector2d v(1.0, 2.0);
  const Eigen::Matrix2d a = v * v.transpose();
  SmallCholesky<2> chol;
  EXPECT_FALSE(chol.compute(a));
  EXPECT_FALSE(chol.ok());
  Eigen::Vector2d x = a * Eigen::Vector2d(3.0, 0.0);  // a consistent right-hand side
  chol.solveInPlace(x);
  ASSERT_TRUE(x.allFinite());
  EXPECT_LT((a * x - a * Eigen::Vector2d(3.0, 0.0)).norm(), 1e-12);
}
