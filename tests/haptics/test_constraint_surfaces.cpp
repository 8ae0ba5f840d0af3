// Implicit surfaces, contact classification (thesis 3.1) and the Generic Penalty Method (3.15)-(3.16).
#include <gtest/gtest.h>

#include "haptics/constraints/penalty_contact.hpp"
#include "haptics/model/dynamics.hpp"
#include "haptics/model/kinematics.hpp"
#include "haptics/sim/integrator.hpp"
#include "robot_fixtures.hpp"

namespace needle::haptics {
namespace {

using Eigen::Vector3d;

void expect_consistent_derivatives(const ImplicitSurface& s, const Vector3d& x) {
  const double eps = 1e-6;
  const SurfaceSample at = s.evaluate(x);
  EXPECT_NEAR(at.gradient.norm(), 1.0, 1e-12);
  for (int i = 0; i < 3; ++i) {
    const Vector3d e = Vector3d::Unit(i) * eps;
    const SurfaceSample plus = s.evaluate(x + e), minus = s.evaluate(x - e);
    EXPECT_NEAR(at.gradient[i], (plus.phi - minus.phi) / (2 * eps), 1e-7) << "x " << x.transpose();
    EXPECT_LT((at.hessian.col(i) - (plus.gradient - minus.gradient) / (2 * eps)).norm(), 1e-5) << "x " << x.transpose();
  }
}

TEST(ConstraintSurfaces, ThesisSphereHasSignedDistanceAndUnitGradient) {
  const ImplicitSurface sphere{SurfacePrimitive::sphere({0.4, 0, 0}, 0.1)};
  EXPECT_NEAR(sphere.evaluate({0.25, 0, 0}).phi, 0.05, 1e-15);
  EXPECT_NEAR(sphere.evaluate({0.4, 0.08, 0}).phi, -0.02, 1e-15);
  EXPECT_TRUE(sphere.evaluate({0.25, 0, 0}).gradient.isApprox(Vector3d(-1, 0, 0)));
  for (const Vector3d& x : {Vector3d(0.3, 0.05, -0.02), Vector3d(0.45, -0.1, 0.2)})
    expect_consistent_derivatives(sphere, x);
}

TEST(ConstraintSurfaces, PlaneAndCapsuleDerivativesMatchFiniteDifferences) {
  const ImplicitSurface plane{SurfacePrimitive::plane({0, 0, 0.1}, {0, 0, 2})};
  EXPECT_NEAR(plane.evaluate({5, -3, 0.25}).phi, 0.15, 1e-15);
  expect_consistent_derivatives(plane, {0.1, 0.2, 0.3});
  const ImplicitSurface capsule{SurfacePrimitive::capsule({0, 0, 0}, {0.2, 0, 0}, 0.05)};
  EXPECT_NEAR(capsule.evaluate({0.1, 0.08, 0}).phi, 0.03, 1e-15);  // beside the cylinder
  EXPECT_NEAR(capsule.evaluate({0.3, 0, 0}).phi, 0.05, 1e-15);     // beyond the cap
  for (const Vector3d& x : {Vector3d(0.1, 0.03, 0.04), Vector3d(-0.05, 0.02, 0.01), Vector3d(0.26, -0.01, 0.03)})
    expect_consistent_derivatives(capsule, x);
}

TEST(ConstraintSurfaces, UnionAndIntersectionCompose) {
  const auto a = SurfacePrimitive::sphere({0, 0, 0}, 0.1), b = SurfacePrimitive::sphere({0.15, 0, 0}, 0.1);
  const ImplicitSurface both{{a, b}, ImplicitSurface::Combine::Union};
  const ImplicitSurface lens{{a, b}, ImplicitSurface::Combine::Intersection};
  const Vector3d x(0.2, 0, 0);  // inside b only
  EXPECT_LT(both.evaluate(x).phi, 0.0);
  EXPECT_GT(lens.evaluate(x).phi, 0.0);
  EXPECT_LT(lens.evaluate({0.075, 0, 0}).phi, 0.0);  // inside both
}

TEST(ConstraintSurfaces, SecondDerivativeAlongAPathMatchesFiniteDifferences) {
  const ImplicitSurface sphere{SurfacePrimitive::sphere({0.4, 0, 0}, 0.1)};
  auto x = [](double t) { return Vector3d(0.3 + 0.02 * std::sin(3 * t), 0.05 * t * t, 0.01 * std::cos(t)); };
  auto v = [](double t) { return Vector3d(0.06 * std::cos(3 * t), 0.1 * t, -0.01 * std::sin(t)); };
  auto a = [](double t) { return Vector3d(-0.18 * std::sin(3 * t), 0.1, -0.01 * std::cos(t)); };
  const double t = 0.7, h = 1e-4;
  const SurfaceMotion m = surface_motion(sphere.evaluate(x(t)), v(t), a(t));
  const double p0 = sphere.evaluate(x(t - h)).phi, p1 = sphere.evaluate(x(t)).phi, p2 = sphere.evaluate(x(t + h)).phi;
  EXPECT_NEAR(m.phi_dot, (p2 - p0) / (2 * h), 1e-8);
  EXPECT_NEAR(m.phi_ddot, (p2 - 2 * p1 + p0) / (h * h), 1e-5);
}

TEST(ConstraintSurfaces, ContactClassificationFollowsTheSignOfPhi) {
  EXPECT_EQ(classify_contact(1e-3, 1e-6), SurfaceContact::Free);
  EXPECT_EQ(classify_contact(5e-7, 1e-6), SurfaceContact::OnSurface);
  EXPECT_EQ(classify_contact(-1e-3, 1e-6), SurfaceContact::Penetrating);
}

TEST(ConstraintSurfaces, GpmMultiplierIsPrintedFormulaWithThesisGains) {
  const GpmParams p;  // α = 0.02, ξ = 100, ω = 200
  EXPECT_DOUBLE_EQ(gpm_multiplier(p, {-1e-3, -0.01, 0.5}, 0.0), 0.02 * (0.5 + 2 * 100 * 200 * -0.01 + 40000 * -1e-3));
  EXPECT_DOUBLE_EQ(p.stiffness(), 800.0);
  EXPECT_DOUBLE_EQ(p.damping(), 800.0);
  SurfaceSample s;
  s.gradient = Vector3d(0, 0, 1);
  EXPECT_TRUE(gpm_force(s, -2.0).isApprox(Vector3d(0, 0, -2)));  // the tool presses into the surface
}

TEST(ConstraintSurfaces, GpmMultiplierTakesDampingAndStiffnessAtTheEndOfTheStep) {
  const GpmParams p{1.0, 1.0, 1.0};  // α = ξ = ω = 1: λ = φ̈ + 2 φ̇⁺ + φ⁺
  // h = 0.5, φ = −1, φ̇ = −2, φ̈ = 4: φ̇⁺ = −2 + 0.5·4 = 0, φ⁺ = −1 + 0.5·(−2) + 0.25·4 = −1,
  // λ = 4 + 0 − 1 = 3 (the printed form at the same state: 4 − 4 − 1 = −1).
  EXPECT_DOUBLE_EQ(gpm_multiplier(p, {-1.0, -2.0, 4.0}, 0.5), 3.0);
  EXPECT_DOUBLE_EQ(gpm_multiplier(p, {-1.0, -2.0, 4.0}, 0.0), -1.0);
  // Its slope in φ̈, which penalty_acceleration solves with: 1 + 2h + h² = 2.25.
  EXPECT_DOUBLE_EQ(gpm_multiplier(p, {0.0, 0.0, 1.0}, 0.5), 2.25);
}

class PenaltyOnRobot : public ::testing::Test {
 protected:
  RobotModel model = test::virtual_robot();
  RobotData data{model};
  ImplicitSurface plane;
  VecN q = VecN::Zero(5), dq = VecN::Zero(5);

  void SetUp() override {
    model.gravity.setZero();
    q << 0.1, 0.6, -1.4, 0.2, 0.5;
    update_kinematics(model, data, q, dq);
    // A floor 1 mm above the tip, so the tip starts 1 mm inside.
    plane = ImplicitSurface{SurfacePrimitive::plane(data.tip.translation() + Vector3d(0, 0, 0.001), {0, 0, 1})};
  }
};

TEST_F(PenaltyOnRobot, SolvedMultiplierSatisfiesTheGpmEquationWithItsOwnAcceleration) {
  std::mt19937 rng(3);
  for (double step : {0.0, 5e-4}) {
    dq = test::random_vector(rng, 5, 0.5);
    update_kinematics(model, data, q, dq);
    update_dynamics(model, data);
    const VecN tau = test::random_vector(rng, 5, 0.05);
    VecN ddq(5);
    const SurfaceSample s = plane.evaluate(data.tip.translation());
    PenaltyResult r = penalty_acceleration(GpmParams{}, model, data, s, tau, step, ddq);
    if (!r.active) {  // this random state would pull: reverse the velocity to press instead
      dq = -dq;
      update_kinematics(model, data, q, dq);
      update_dynamics(model, data);
      r = penalty_acceleration(GpmParams{}, model, data, s, tau, step, ddq);
    }
    ASSERT_TRUE(r.active);
    // The dynamics with the contact torque −J_φᵀλ hold.
    const Eigen::Matrix<double, 1, 5> j_phi = s.gradient.transpose() * data.J.topRows<3>();
    const VecN residual =
        data.H * ddq + data.C * dq + model.damping().cwiseProduct(dq) + data.g - tau + j_phi.transpose() * r.lambda;
    EXPECT_LT(residual.norm(), 1e-10);
    // And λ is (3.15) evaluated with φ̈ from that acceleration (implicit-Euler variant for step > 0).
    const Vector3d acc = data.J.topRows<3>() * ddq + data.Jdot.topRows<3>() * dq;
    const SurfaceMotion m = surface_motion(s, data.tip_twist.head<3>(), acc);
    const GpmParams p;
    const double c = p.damping() / p.alpha, k = p.omega * p.omega, h = step;
    const double expected =
        p.alpha * (m.phi_ddot + c * (m.phi_dot + h * m.phi_ddot) + k * (m.phi + h * m.phi_dot + h * h * m.phi_ddot));
    EXPECT_NEAR(r.lambda, expected, 1e-9 * std::abs(expected));
  }
}

TEST_F(PenaltyOnRobot, SteadyPressGivesPenetrationForceOverStiffness) {
  // Press with 1 N straight down at the tip; at rest the penalty is a spring αω² = 800 N/m.
  const GpmParams p;
  const Vector3d push(0, 0, -1.0);
  const double h = 5e-4;
  VecN ddq(5);
  for (int step = 0; step < 20000; ++step) {  // 10 s: the slow penalty root is ω/(2ξ) = 1 /s
    update_kinematics(model, data, q, dq);
    update_dynamics(model, data);
    // Joint damping added so the free directions settle too.
    const VecN tau = data.J.topRows<3>().transpose() * push - 0.05 * dq;
    penalty_acceleration(p, model, data, plane.evaluate(data.tip.translation()), tau, h, ddq);
    dq += h * ddq;
    q += h * dq;
  }
  update_kinematics(model, data, q, dq);
  EXPECT_NEAR(plane.evaluate(data.tip.translation()).phi, -1.0 / p.stiffness(), 2e-5);
}

}  // namespace
}  // namespace needle::haptics
