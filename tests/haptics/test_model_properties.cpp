// Structural properties of the dynamics of both product robots at random states (thesis 2.3.1).
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>

#include "haptics/model/dynamics.hpp"
#include "haptics/model/kinematics.hpp"
#include "haptics/model/regressor.hpp"
#include "haptics/sim/integrator.hpp"
#include "robot_fixtures.hpp"

namespace needle::haptics {
namespace {

class ModelProperties : public ::testing::TestWithParam<const char*> {
 protected:
  RobotModel model = std::string(GetParam()) == "master" ? test::master_robot() : test::virtual_robot();
  RobotData data{model};
  std::mt19937 rng{42};
  int n = model.dof();

  void at(const VecN& q, const VecN& dq) {
    update_kinematics(model, data, q, dq);
    update_dynamics(model, data);
  }
};

TEST_P(ModelProperties, InertiaIsSymmetricPositiveDefinite) {
  for (int trial = 0; trial < 50; ++trial) {
    at(test::random_vector(rng, n, 3.0), test::random_vector(rng, n, 2.0));
    EXPECT_LT((data.H - data.H.transpose()).norm(), 1e-15);
    Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(Eigen::MatrixXd(data.H));
    EXPECT_GT(eig.eigenvalues().minCoeff(), 0.0);
  }
}

TEST_P(ModelProperties, HdotMinusTwoCIsSkewSymmetric) {
  const double eps = 1e-6;
  for (int trial = 0; trial < 20; ++trial) {
    const VecN q = test::random_vector(rng, n, 3.0), dq = test::random_vector(rng, n, 2.0);
    at(q + eps * dq, dq);
    const MatN h_plus = data.H;
    at(q - eps * dq, dq);
    const MatN h_dot = (h_plus - data.H) / (2 * eps);  // dH/dt along q̇
    at(q, dq);
    const MatN n_mat = h_dot - 2.0 * data.C;
    EXPECT_LT((n_mat + n_mat.transpose()).norm(), 1e-7 * (1.0 + h_dot.norm())) << "trial " << trial;
    // Skew-symmetry of Ḣ − 2C is what makes q̇ᵀ(Ḣ − 2C)q̇ = 0 (passivity).
    EXPECT_NEAR(dq.dot(n_mat * dq), 0.0, 1e-9);
  }
}

TEST_P(ModelProperties, RegressorTimesParametersEqualsDirectEvaluation) {
  const ParamVec theta = parameter_vector(model);
  RegressorMat Y;
  for (int trial = 0; trial < 20; ++trial) {
    const VecN q = test::random_vector(rng, n, 3.0), dq = test::random_vector(rng, n, 2.0),
               ddq = test::random_vector(rng, n, 5.0);
    at(q, dq);
    const VecN direct = data.H * ddq + data.C * dq + model.damping().cwiseProduct(dq) + data.g;
    regressor(model, data, ddq, Y);
    VecN rnea(n);
    inverse_dynamics(model, data, theta, ddq, rnea);
    EXPECT_LT((Y * theta - direct).norm(), 1e-10 * (1.0 + direct.norm()));
    EXPECT_LT((rnea - direct).norm(), 1e-10 * (1.0 + direct.norm()));
  }
}

TEST_P(ModelProperties, JacobianMatchesFiniteDifferencesOfForwardKinematics) {
  const double eps = 1e-6;
  for (int trial = 0; trial < 20; ++trial) {
    const VecN q = test::random_vector(rng, n, 3.0);
    at(q, VecN::Zero(n));
    for (int j = 0; j < n; ++j) {
      VecN dq = VecN::Zero(n);
      dq[j] = eps;
      const Eigen::Isometry3d plus = tip_pose(model, q + dq), minus = tip_pose(model, q - dq);
      const Eigen::Vector3d v = (plus.translation() - minus.translation()) / (2 * eps);
      // Angular velocity from the relative rotation between the two poses (base frame).
      const Eigen::AngleAxisd rel(plus.linear() * minus.linear().transpose());
      const Eigen::Vector3d w = rel.axis() * rel.angle() / (2 * eps);
      EXPECT_LT((data.J.col(j).head<3>() - v).norm(), 1e-8) << "joint " << j;
      EXPECT_LT((data.J.col(j).tail<3>() - w).norm(), 1e-8) << "joint " << j;
    }
  }
}

TEST_P(ModelProperties, JacobianRateMatchesFiniteDifferenceAlongMotion) {
  const double eps = 1e-6;
  for (int trial = 0; trial < 20; ++trial) {
    const VecN q = test::random_vector(rng, n, 3.0), dq = test::random_vector(rng, n, 2.0);
    at(q + eps * dq, dq);
    const Mat6N j_plus = data.J;
    at(q - eps * dq, dq);
    const Mat6N j_minus = data.J;
    at(q, dq);
    EXPECT_LT((data.Jdot - (j_plus - j_minus) / (2 * eps)).norm(), 1e-7);
    EXPECT_LT((data.tip_twist - data.J * dq).norm(), 1e-12);
  }
}

TEST_P(ModelProperties, TickPathMatchesTheFullDynamics) {
  // Composite-rigid-body H and Newton-Euler bias against the centre-of-mass-Jacobian route.
  RobotData fast(model);
  for (int trial = 0; trial < 20; ++trial) {
    const VecN q = test::random_vector(rng, n, 3.0), dq = test::random_vector(rng, n, 2.0);
    at(q, dq);
    update_frames(model, fast, q, dq);
    update_tick_dynamics(model, fast);
    EXPECT_LT((fast.H - data.H).norm(), 1e-13 * (1.0 + data.H.norm()));
    EXPECT_LT((fast.bias - (data.C * dq + data.g)).norm(), 1e-12 * (1.0 + data.g.norm()));
    EXPECT_TRUE(fast.J.isApprox(data.J, 1e-15));
    EXPECT_TRUE(fast.Jdot.isApprox(data.Jdot, 1e-15));
  }
}

TEST_P(ModelProperties, GravityPassIsTheGradientOfThePotentialEnergy) {
  // update_gravity (Newton-Euler at rest, the controller's compensation) against ∂V/∂q by central
  // differences of the potential energy, and against the centre-of-mass-Jacobian g.
  RobotData fast(model), probe(model);
  for (int trial = 0; trial < 20; ++trial) {
    const VecN q = test::random_vector(rng, n, 3.0), dq = test::random_vector(rng, n, 2.0);
    at(q, dq);
    update_frames(model, fast, q, dq);
    update_gravity(model, fast);
    VecN gradient(n);
    const double eps = 1e-6;
    for (int i = 0; i < n; ++i) {
      VecN qp = q, qm = q;
      qp[i] += eps;
      qm[i] -= eps;
      update_frames(model, probe, qp, dq);
      const double vp = potential_energy(model, probe);
      update_frames(model, probe, qm, dq);
      gradient[i] = (vp - potential_energy(model, probe)) / (2 * eps);
    }
    EXPECT_LT((fast.g - gradient).norm(), 1e-8 * (1.0 + gradient.norm()));
    EXPECT_LT((fast.g - data.g).norm(), 1e-13 * (1.0 + data.g.norm()));
  }
}

TEST_P(ModelProperties, BiasAloneEqualsTheRegressorAtZeroAcceleration) {
  // The controller's master term Y(q, q̇, 0) θ = C q̇ + D q̇ + g (3.20), by update_bias (no H).
  const ParamVec theta = parameter_vector(model);
  const VecN zero = VecN::Zero(n);
  RobotData bias_only(model);
  for (int trial = 0; trial < 20; ++trial) {
    const VecN q = test::random_vector(rng, n, 3.0), dq = test::random_vector(rng, n, 2.0);
    at(q, dq);
    VecN y_theta(n);
    inverse_dynamics(model, data, theta, zero, y_theta);
    update_frames(model, bias_only, q, dq);
    update_bias(model, bias_only);
    EXPECT_LT((bias_only.bias + model.damping().cwiseProduct(dq) - y_theta).norm(), 1e-12 * (1.0 + y_theta.norm()));
  }
}

TEST_P(ModelProperties, InverseThenForwardDynamicsRoundTrips) {
  const ParamVec theta = parameter_vector(model);
  for (int trial = 0; trial < 20; ++trial) {
    const VecN q = test::random_vector(rng, n, 3.0), dq = test::random_vector(rng, n, 2.0),
               ddq = test::random_vector(rng, n, 5.0);
    at(q, dq);
    VecN tau(n), ddq_back(n);
    inverse_dynamics(model, data, theta, ddq, tau);
    forward_dynamics(model, data, tau, ddq_back);
    EXPECT_LT((ddq_back - ddq).norm(), 1e-9 * (1.0 + ddq.norm()));
  }
}

TEST_P(ModelProperties, EnergyIsConservedInUnforcedUndampedMotion) {
  for (auto& joint : model.joints) joint.damping = 0.0;
  VecN q = test::random_vector(rng, n, 1.5), dq = test::random_vector(rng, n, 1.0);
  at(q, dq);
  const double e0 = kinetic_energy(data) + potential_energy(model, data);
  const VecN zero = VecN::Zero(n);
  double worst = 0.0;
  for (int step = 0; step < 2000; ++step) {  // 1 s at 0.5 ms
    integrate_step(Integrator::Rk4, model, data, q, dq, zero, 5e-4);
    worst = std::max(worst, std::abs(kinetic_energy(data) + potential_energy(model, data) - e0));
  }
  const double scale = kinetic_energy(data) + std::abs(potential_energy(model, data)) + 1e-3;
  EXPECT_LT(worst, 1e-6 * scale);
  // With damping the energy must decrease instead: a sign error in D or C would show here.
  RobotModel damped = model;
  for (auto& joint : damped.joints) joint.damping = 0.01;
  RobotData damped_data(damped);
  update_kinematics(damped, damped_data, q, dq);
  update_dynamics(damped, damped_data);
  double previous = kinetic_energy(damped_data) + potential_energy(damped, damped_data);
  for (int step = 0; step < 200; ++step) {
    integrate_step(Integrator::Rk4, damped, damped_data, q, dq, zero, 5e-4);
    const double e = kinetic_energy(damped_data) + potential_energy(damped, damped_data);
    EXPECT_LE(e, previous + 1e-12);
    previous = e;
  }
}

INSTANTIATE_TEST_SUITE_P(Robots, ModelProperties, ::testing::Values("master", "virtual"));

}  // namespace
}  // namespace needle::haptics
