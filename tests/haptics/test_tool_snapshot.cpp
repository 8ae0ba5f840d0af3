// needle_axis: the snapshot's quaternion applied to the body x axis, against Eigen's rotation.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <random>

#include "haptics/realtime/tool_snapshot.hpp"

namespace needle::haptics {
namespace {

TEST(ToolSnapshot, NeedleAxisIsTheOrientationAppliedToTheBodyXAxis) {
  std::mt19937 rng(7);
  std::normal_distribution<double> n;
  for (int i = 0; i < 200; ++i) {
    const Eigen::Quaterniond q = Eigen::Quaterniond(n(rng), n(rng), n(rng), n(rng)).normalized();
    ToolSnapshot s;
    s.needle_orientation[0] = q.w();
    s.needle_orientation[1] = q.x();
    s.needle_orientation[2] = q.y();
    s.needle_orientation[3] = q.z();
    const Eigen::Vector3d expected = q.toRotationMatrix().col(0);
    const auto axis = needle_axis(s);
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(axis[k], expected[k], 1e-12) << "quaternion " << i;
  }
  EXPECT_EQ(needle_axis(ToolSnapshot{}), (std::array<double, 3>{1.0, 0.0, 0.0}));  // identity: +x
}

}  // namespace
}  // namespace needle::haptics
