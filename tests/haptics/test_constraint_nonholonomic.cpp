// The needle's nonholonomic constraint (4.2): Pfaffian, its projection (2.30), the multipliers
// (3.22) with the stabilization (3.23), and non-integrability (thesis 3.1.1).
#include <gtest/gtest.h>

#include "haptics/constraints/involutivity.hpp"
#include "haptics/constraints/nonholonomic_multiplier.hpp"
#include "haptics/model/dynamics.hpp"
#include "haptics/model/kinematics.hpp"
#include "robot_fixtures.hpp"

namespace needle::haptics {
namespace {

class NeedleConstraint : public ::testing::Test {
 protected:
  RobotModel model = test::virtual_robot();
  RobotData data{model};
  std::mt19937 rng{11};
  TaskPfaffian task;
  MatKN A, A_dot;

  void at(const VecN& q, const VecN& dq) {
    update_kinematics(model, data, q, dq);
    update_dynamics(model, data);
    needle_pfaffian(data.tip.linear(), data.omega[4], task);
    project_pfaffian(task, data.J, data.Jdot, A, A_dot);
  }
  Eigen::MatrixXd joint_pfaffian(const Eigen::VectorXd& q) {
    at(VecN(q), VecN::Zero(5));
    return Eigen::MatrixXd(A);
  }
};

TEST_F(NeedleConstraint, RowsMeasureLateralTipVelocity) {
  const VecN q = test::random_vector(rng, 5, 2.0), dq = test::random_vector(rng, 5, 1.0);
  at(q, dq);
  const Eigen::Vector3d v = data.tip_twist.head<3>();
  const Eigen::Matrix3d R = data.tip.linear();
  const VecK psi = A * dq;
  EXPECT_NEAR(psi[0], R.col(1).dot(v), 1e-14);
  EXPECT_NEAR(psi[1], R.col(2).dot(v), 1e-14);
  // Motion along the needle axis and any rotation are allowed: A_x [x₅; ω] = 0.
  Eigen::Matrix<double, 6, 1> allowed;
  allowed << 0.3 * R.col(0), Eigen::Vector3d(0.2, -1.0, 0.7);
  EXPECT_LT((task.A_x * allowed).norm(), 1e-15);
}

TEST_F(NeedleConstraint, JointPfaffianRateMatchesFiniteDifferences) {
  const double eps = 1e-6;
  for (int trial = 0; trial < 10; ++trial) {
    const VecN q = test::random_vector(rng, 5, 2.0), dq = test::random_vector(rng, 5, 1.0);
    at(q + eps * dq, dq);
    const MatKN plus = A;
    at(q - eps * dq, dq);
    const MatKN minus = A;
    at(q, dq);
    EXPECT_LT((A_dot - (plus - minus) / (2 * eps)).norm(), 1e-7);
  }
}

TEST_F(NeedleConstraint, MultiplierEnforcesTheStabilizedResidualDynamics) {
  NonholonomicMultiplier mult;
  mult.reset(2);
  mult.advance(MatKN::Identity(2, 5), VecN::Constant(5, 0.01), 1.0);  // some nonzero ∫ψ
  const VecN q = test::random_vector(rng, 5, 2.0), dq = test::random_vector(rng, 5, 1.0);
  at(q, dq);
  const VecN tau = test::random_vector(rng, 5, 0.1);
  VecK lambda;
  VecN ddq(5);
  mult.solve(model, data, A, A_dot, tau, lambda, ddq);
  const VecK psi = A * dq;
  const VecK psi_dot = A * ddq + A_dot * dq;
  const NonholonomicGains g;
  EXPECT_LT((psi_dot + 2 * g.alpha * psi + g.beta * mult.psi_integral()).norm(), 1e-9 * (1.0 + psi.norm()));
  const VecN residual =
      data.H * ddq + data.C * dq + model.damping().cwiseProduct(dq) + data.g - tau - A.transpose() * lambda;
  EXPECT_LT(residual.norm(), 1e-10);
}

TEST_F(NeedleConstraint, ResidualDecaysAsTheStabilizationPrescribes) {
  // Start with a lateral velocity; (3.23) with β = α² gives ψ(t) = ψ₀ e^{−αt}(1 − αt).
  NonholonomicMultiplier mult;
  mult.reset(2);
  VecN q(5), dq(5);
  q << 0.1, 0.6, -1.4, 0.2, 0.5;
  dq << 0.4, -0.3, 0.2, 0.5, -0.6;
  at(q, dq);
  const VecK psi0 = A * dq;
  ASSERT_GT(psi0.norm(), 0.01);
  const double h = 2e-5, alpha = mult.gains().alpha;
  const VecN tau = VecN::Constant(5, 0.02);
  VecK lambda;
  VecN ddq(5);
  double worst = 0.0;
  for (int step = 1; step <= 5000; ++step) {  // 0.1 s = 5/α
    mult.solve(model, data, A, A_dot, tau, lambda, ddq);
    mult.advance(A, dq, h);
    dq += h * ddq;
    q += h * dq;
    at(q, dq);
    const double t = step * h;
    const VecK expected = psi0 * std::exp(-alpha * t) * (1.0 - alpha * t);
    worst = std::max(worst, (A * dq - expected).norm());
  }
  EXPECT_LT(worst, 0.01 * psi0.norm());
  EXPECT_LT((A * dq).norm(), 0.03 * psi0.norm());  // e^{-5}·4 ≈ 0.027 at t = 5/α
}

TEST_F(NeedleConstraint, DistributionIsNotInvolutive) {
  for (int trial = 0; trial < 5; ++trial) {
    const Eigen::VectorXd q = Eigen::VectorXd(test::random_vector(rng, 5, 2.0));
    EXPECT_GT(involutivity_defect([&](const Eigen::VectorXd& x) { return joint_pfaffian(x); }, q), 0.01);
  }
}

TEST(Involutivity, ThesisPlanarExampleHasUnitBracketOutsideTheDistribution) {
  // (3.4)-(3.5): A = [−sin θ, cos θ, 0] on (x, y, θ); [g₁, g₂] = ±(−sin θ, cos θ, 0), so |A[g₁, g₂]| = 1.
  auto A = [](const Eigen::VectorXd& q) {
    Eigen::MatrixXd a(1, 3);
    a << -std::sin(q[2]), std::cos(q[2]), 0.0;
    return a;
  };
  EXPECT_NEAR(involutivity_defect(A, Eigen::Vector3d(0.3, -0.2, 0.8)), 1.0, 1e-6);
}

TEST(Involutivity, GradientOfAFunctionIsInvolutive) {
  // A holonomic constraint's Pfaffian A = ∂φ/∂q is integrable: the check must report ~0.
  auto A = [](const Eigen::VectorXd& q) {
    Eigen::MatrixXd a(1, 4);
    a << 2 * q[0] + q[1], q[0] + std::cos(q[1]), 3 * q[2] * q[2],
        std::exp(q[3]);  // ∇(q₀² + q₀q₁ + sin q₁ + q₂³ + e^{q₃})
    return a;
  };
  EXPECT_LT(involutivity_defect(A, Eigen::Vector4d(0.3, -0.2, 0.8, 0.1)), 1e-6);
}

}  // namespace
}  // namespace needle::haptics
