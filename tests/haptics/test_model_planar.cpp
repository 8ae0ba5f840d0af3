// A planar two-link arm against its textbook closed forms (e.g. Spong, Hutchinson, Vidyasagar,
// "Robot Modeling and Control", §7.4.2): an independent check of FK, J, H, C q̇ and g.
#include <gtest/gtest.h>

#include <cmath>

#include "haptics/model/dynamics.hpp"
#include "haptics/model/kinematics.hpp"
#include "robot_fixtures.hpp"

namespace needle::haptics {
namespace {

using namespace test::planar;

TEST(ModelPlanar, MatchesClosedForms) {
  const RobotModel model = arm();
  RobotData data(model);
  for (double a : {-1.0, 0.3, 2.0}) {
    for (double b : {-2.5, 0.0, 0.8}) {
      VecN q(2), dq(2);
      q << a, b;
      dq << 0.7, -1.3;
      update_kinematics(model, data, q, dq);
      update_dynamics(model, data);
      const double c2 = std::cos(b), s2 = std::sin(b);
      EXPECT_NEAR(data.tip.translation().x(), l1 * std::cos(a) + l2 * std::cos(a + b), 1e-14);
      EXPECT_NEAR(data.tip.translation().y(), l1 * std::sin(a) + l2 * std::sin(a + b), 1e-14);
      EXPECT_NEAR(data.J(0, 0), -l1 * std::sin(a) - l2 * std::sin(a + b), 1e-14);
      EXPECT_NEAR(data.J(1, 1), l2 * std::cos(a + b), 1e-14);
      EXPECT_NEAR(data.J(5, 0), 1.0, 1e-15);
      const double h11 = m1 * lc1 * lc1 + i1 + m2 * (l1 * l1 + lc2 * lc2 + 2 * l1 * lc2 * c2) + i2;
      const double h12 = m2 * (lc2 * lc2 + l1 * lc2 * c2) + i2;
      const double h22 = m2 * lc2 * lc2 + i2;
      EXPECT_NEAR(data.H(0, 0), h11, 1e-13);
      EXPECT_NEAR(data.H(0, 1), h12, 1e-13);
      EXPECT_NEAR(data.H(1, 0), h12, 1e-13);
      EXPECT_NEAR(data.H(1, 1), h22, 1e-13);
      const double hh = -m2 * l1 * lc2 * s2;  // Christoffel coefficient
      const VecN cdq = data.C * dq;
      EXPECT_NEAR(cdq[0], hh * dq[1] * dq[1] + 2 * hh * dq[0] * dq[1], 1e-13);
      EXPECT_NEAR(cdq[1], -hh * dq[0] * dq[0], 1e-13);
      EXPECT_NEAR(data.g[0], (m1 * lc1 + m2 * l1) * g0 * std::cos(a) + m2 * lc2 * g0 * std::cos(a + b), 1e-12);
      EXPECT_NEAR(data.g[1], m2 * lc2 * g0 * std::cos(a + b), 1e-12);
    }
  }
}

}  // namespace
}  // namespace needle::haptics
