#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "haptics/devices/falcon/falcon_kinematics.hpp"

namespace needle::haptics::falcon {
namespace {

constexpr double kDeg = M_PI / 180.0;

std::vector<Vec3> workspace_grid() {
  std::vector<Vec3> points;
  for (double x = -0.04; x <= 0.0401; x += 0.02)
    for (double y = -0.04; y <= 0.0401; y += 0.02)
      for (double z = 0.09; z <= 0.1501; z += 0.02) points.push_back({x, y, z});
  return points;
}

// Central difference of the hip angles when the handle moves by +-h along `axis`.
Vec3 hip_change(const Geometry& g, const Vec3& x, int axis, double h) {
  Vec3 plus = x, minus = x;
  plus[axis] += h;
  minus[axis] -= h;
  LegAngles ap, am;
  EXPECT_TRUE(inverse_kinematics(g, plus, ap));
  EXPECT_TRUE(inverse_kinematics(g, minus, am));
  return {ap.hip[0] - am.hip[0], ap.hip[1] - am.hip[1], ap.hip[2] - am.hip[2]};
}

TEST(FalconEncoder, CountsToHipAngleThroughTheCapstan) {
  const Drive drive;
  EXPECT_NEAR(encoder_to_hip_angle(drive, 0), 35.0 * kDeg, 1e-15);
  // 1000 counts = 1000/1280 motor turns; x 14.25/110 = 0.1012074 arm turns = 36.434659 deg.
  EXPECT_NEAR(encoder_to_hip_angle(drive, 1000), (35.0 + 36.43465909090909) * kDeg, 1e-12);
  // One motor turn backwards: the arm turns 14.25/110 of a turn = 46.636364 deg.
  EXPECT_NEAR(encoder_to_hip_angle(drive, -1280), (35.0 - 46.63636363636364) * kDeg, 1e-12);
}

TEST(FalconEncoder, TorqueCommandIsNegatedScaledAndClamped) {
  const Drive drive;
  EXPECT_EQ(torque_to_command(drive, 0.1), -1000);
  EXPECT_EQ(torque_to_command(drive, -0.25), 2500);
  EXPECT_EQ(torque_to_command(drive, 10.0), -32767);
}

// Reference hip angles from the other published closed form: libnifalcon's
// FalconKinematicStamper::IK solves the same leg as a quadratic in tan(t1 / 2)
// (l0 + l1 T + l2 T^2 = 0); evaluated separately for these positions.
TEST(FalconKinematics, InverseMatchesTheHalfAngleQuadraticSolution) {
  const Geometry g;
  LegAngles a;
  ASSERT_TRUE(inverse_kinematics(g, {0.0, 0.0, 0.11}, a));
  for (int leg = 0; leg < 3; ++leg) EXPECT_NEAR(a.hip[leg], 16.187960008871805 * kDeg, 1e-12);
  ASSERT_TRUE(inverse_kinematics(g, {0.02, -0.01, 0.13}, a));
  EXPECT_NEAR(a.hip[0], 42.374451891037474 * kDeg, 1e-12);
  EXPECT_NEAR(a.hip[1], 20.06128809031251 * kDeg, 1e-12);
  EXPECT_NEAR(a.hip[2], 37.52490027544805 * kDeg, 1e-12);
}

TEST(FalconKinematics, InverseSatisfiesEveryLegsForwardEquations) {
  const Geometry g;
  for (const Vec3& x : workspace_grid()) {
    LegAngles a;
    ASSERT_TRUE(inverse_kinematics(g, x, a)) << x[0] << " " << x[1] << " " << x[2];
    for (int leg = 0; leg < 3; ++leg) {
      const double cp = std::cos(g.phi[leg]), sp = std::sin(g.phi[leg]);
      const double length = g.d + g.e + g.b * std::sin(a.shin[leg]);
      // Rebuild the handle centre from the three leg angles, then back to the base frame.
      const double u = g.a * std::cos(a.hip[leg]) + length * std::cos(a.knee[leg]) - g.c;
      const double v = g.b * std::cos(a.shin[leg]) - g.f;
      const double w = g.a * std::sin(a.hip[leg]) + length * std::sin(a.knee[leg]);
      const double bu = u + g.r, bv = v + g.s;
      EXPECT_NEAR(cp * bu - sp * bv, x[0], 1e-12);
      EXPECT_NEAR(sp * bu + cp * bv, x[1], 1e-12);
      EXPECT_NEAR(w, x[2], 1e-12);
    }
  }
}

TEST(FalconKinematics, ForwardByNewtonInvertsTheInverse) {
  const Geometry g;
  for (const Vec3& x : workspace_grid()) {
    LegAngles a;
    ASSERT_TRUE(inverse_kinematics(g, x, a));
    Vec3 back{};
    ASSERT_TRUE(forward_kinematics(g, a.hip, {0.0, 0.0, 0.12}, back)) << x[0] << " " << x[1] << " " << x[2];
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(back[i], x[i], 1e-10);
  }
}

TEST(FalconKinematics, UnreachablePositionsAreReported) {
  const Geometry g;
  LegAngles a;
  EXPECT_FALSE(inverse_kinematics(g, {0.0, 0.0, 0.5}, a));
  Vec3 x{};
  EXPECT_FALSE(forward_kinematics(g, {0.0, 0.0, 0.0}, {0.0, 0.0, 0.5}, x));
}

TEST(FalconKinematics, JacobianEqualsFiniteDifferencesOfTheInverse) {
  const Geometry g;
  const double h = 1e-6;
  for (const Vec3& x : workspace_grid()) {
    Mat3 jac;
    ASSERT_TRUE(hip_jacobian(g, x, jac));
    for (int col = 0; col < 3; ++col) {
      const Vec3 change = hip_change(g, x, col, h);
      for (int leg = 0; leg < 3; ++leg)
        EXPECT_NEAR(jac[leg][col], change[leg] / (2 * h), 1e-6 * (1.0 + std::abs(jac[leg][col])));
    }
  }
}

TEST(FalconKinematics, TorquesDoTheSameVirtualWorkAsTheForce) {
  const Geometry g;
  const Vec3 force = {1.5, -2.0, 4.0};
  for (const Vec3& x : workspace_grid()) {
    Vec3 tau{};
    ASSERT_TRUE(torques_for_force(g, x, force, 1e9, tau));
    // Move the handle a little along each axis: tau . dtheta must equal F . dx.
    for (int axis = 0; axis < 3; ++axis) {
      const double h = 1e-7;
      const Vec3 change = hip_change(g, x, axis, h);
      double work = 0.0;
      for (int leg = 0; leg < 3; ++leg) work += tau[leg] * change[leg];
      EXPECT_NEAR(work, force[axis] * 2 * h, 1e-6 * 2 * h * (1.0 + std::abs(force[axis])));
    }
  }
}

TEST(FalconKinematics, SaturationScalesAllTorquesKeepingTheForceDirection) {
  const Geometry g;
  const Vec3 x = {0.01, 0.02, 0.12};
  Vec3 free{}, limited{};
  ASSERT_TRUE(torques_for_force(g, x, {30.0, 10.0, -20.0}, 1e9, free));
  const double largest = std::max({std::abs(free[0]), std::abs(free[1]), std::abs(free[2])});
  ASSERT_TRUE(torques_for_force(g, x, {30.0, 10.0, -20.0}, largest / 4, limited));
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(limited[i], free[i] / 4, 1e-12);
}

}  // namespace
}  // namespace needle::haptics::falcon
