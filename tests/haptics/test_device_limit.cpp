// The device's force limit in its motors' torques (haptics/control/device_limit.hpp): at the nominal
// pose the torques it lets through make exactly the stated force at the tip; elsewhere it does not
// depend on the pose, so near a singular pose the weight compensation passes whole; and the room it
// leaves a damper.
#include <gtest/gtest.h>

#include "haptics/control/device_limit.hpp"
#include "haptics/model/dynamics.hpp"
#include "haptics/model/kinematics.hpp"
#include "sim_fixtures.hpp"

namespace needle::haptics {
namespace {

// The tip's force that actuated torques make at pose q, by solving J_aᵀ F = τ_a (the 3 × 3 case).
Eigen::Vector3d tip_force(const RobotModel& model, const VecN& q, const VecN& tau) {
  RobotData d(model);
  update_kinematics(model, d, q, VecN::Zero(model.dof()));
  const Eigen::Matrix3d jt = d.J.topLeftCorner(3, 3).transpose();
  return jt.fullPivLu().solve(tau.head(3));
}

VecN nominal_pose(const RobotModel& model, const DeviceParams& device) {
  VecN q(model.dof());
  for (int i = 0; i < model.dof(); ++i) q[i] = device.nominal_pose_rad[static_cast<size_t>(i)];
  return q;
}

TEST(DeviceLimit, AtTheNominalPoseTheLimitedTorquesMakeTheStatedForceInTheirOwnDirection) {
  const RobotModel& omni = test::scenario("nonholonomic_needle").master;
  const DeviceParams device;
  const DeviceLimit limit = device_limit(omni, device);
  const VecN q = nominal_pose(omni, device);
  VecN tau(5);
  tau << 0.4, -0.3, 0.2, 0.05, -0.02;  // well past the limit, with torques on the unactuated wrist
  const Eigen::Vector3d asked = tip_force(omni, q, tau);
  ASSERT_GT(asked.norm(), device.force_limit_N);
  const double kappa = limit_to_device(limit, tau);
  EXPECT_NEAR(kappa, device.force_limit_N / asked.norm(), 1e-12);
  const Eigen::Vector3d given = tip_force(omni, q, tau);
  EXPECT_NEAR(given.norm(), device.force_limit_N, 1e-9);
  EXPECT_NEAR(given.normalized().dot(asked.normalized()), 1.0, 1e-12);
  EXPECT_EQ(tau[3], 0.0);  // no motor on the wrist
  EXPECT_EQ(tau[4], 0.0);
  // Within the limit: untouched but for the wrist.
  VecN small = 0.1 * tau;
  small[4] = 0.01;
  const VecN before = small;
  EXPECT_EQ(limit_to_device(limit, small), 1.0);
  EXPECT_EQ(small.head(3), before.head(3));
  EXPECT_EQ(small[4], 0.0);
}

// With the arm stretched (the stress sweep's singular pose) and just off it, the torque that holds the
// device's weight is one the motors can give: it passes whole, as on the device. A limit on the tip
// force through the present Jacobian would count it as tens of newtons there.
TEST(DeviceLimit, NearTheStretchedArmsSingularityTheWeightCompensationPassesWhole) {
  const RobotModel& omni = test::scenario("nonholonomic_needle").master;
  const DeviceLimit limit = device_limit(omni, DeviceParams{});
  for (double off : {0.0, 1e-3, 1e-2}) {
    VecN q(5);
    q << 0.0, 0.0, off, 0.0, 0.5;
    RobotData d(omni);
    update_kinematics(omni, d, q, VecN::Zero(5));
    update_dynamics(omni, d);
    VecN tau = d.g;
    tau.tail(2).setZero();
    const VecN g = tau;
    EXPECT_EQ(limit_to_device(limit, tau), 1.0) << "q3 = " << off;
    EXPECT_EQ(tau, g);
    if (off > 0.0) {
      EXPECT_GT(tip_force(omni, q, g).norm(), 10.0 * DeviceParams{}.force_limit_N) << "q3 = " << off;
    }
  }
}

TEST(DeviceLimit, TheRoomLeftADamperBringsTheForceToTheLimitAndNoFurther) {
  const RobotModel& omni = test::scenario("nonholonomic_needle").master;
  const DeviceParams device;
  const DeviceLimit limit = device_limit(omni, device);
  const VecN q = nominal_pose(omni, device);
  VecN tau(5), h(5);
  tau << 0.05, 0.1, -0.05, 0.0, 0.0;
  h << 0.02, -0.03, 0.01, 0.0, 0.0;
  ASSERT_LT(tip_force(omni, q, tau).norm(), device.force_limit_N);
  const double beta = room_within_limit(limit, tau, h);
  ASSERT_TRUE(std::isfinite(beta));
  EXPECT_GT(beta, 0.0);
  EXPECT_NEAR(tip_force(omni, q, tau - beta * h).norm(), device.force_limit_N, 1e-9);
  EXPECT_GT(tip_force(omni, q, tau - 1.01 * beta * h).norm(), device.force_limit_N);
  // A command on the limit has no room for a damper that would push it further out.
  VecN at_limit = 100.0 * tau;
  limit_to_device(limit, at_limit);
  const VecN outward = -at_limit;
  EXPECT_NEAR(room_within_limit(limit, at_limit, outward), 0.0, 1e-12);
  // No torque, no bound.
  EXPECT_TRUE(std::isinf(room_within_limit(limit, tau, VecN::Zero(5))));
}

}  // namespace
}  // namespace needle::haptics
