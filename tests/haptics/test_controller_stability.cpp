// The virtual robot's law as printed (3.14) feeds velocity back positively and diverges; the
// corrected law converges to the master (docs/CONTROLLER.md). Contact terms switch in without a
// torque jump. (Force tracking with the derived signs is asserted on the closed loop, test_sim_*.)
#include <gtest/gtest.h>

#include "haptics/control/teleoperation.hpp"
#include "haptics/model/kinematics.hpp"
#include "robot_fixtures.hpp"

namespace needle::haptics {
namespace {

class ControllerLoop : public ::testing::Test {
 protected:
  RobotModel master = test::master_robot();
  RobotModel virt = test::virtual_robot();
  VecN home = (VecN(5) << 0.0, 1.0, -1.6, 0.0, 0.5).finished();

  // Master held still at `q_m`; virtual starts displaced by `offset`. Returns the final joint
  // distance, or infinity when the state stopped being finite.
  double hold_and_settle(VirtualFeedback feedback, const VecN& offset, double seconds) {
    TeleoperationGains gains = thesis_holonomic_gains(5);
    gains.virtual_feedback = feedback;
    Teleoperation tele(master, virt, Scene{}, gains, 0.002, 4);
    tele.reset(home, VecN::Zero(5));
    tele.place_virtual(home + offset, VecN::Zero(5));
    const TickInput in{home, VecN::Zero(5), Wrench::Zero()};
    for (int k = 0; k < static_cast<int>(seconds / 0.002); ++k) {
      tele.step(in);
      if (!tele.world().q().allFinite() || !tele.world().dq().allFinite())
        return std::numeric_limits<double>::infinity();
    }
    return (tele.world().q() - home).norm();
  }
};

TEST_F(ControllerLoop, CorrectedVirtualLawConvergesAndPrintedOneDiverges) {
  virt.gravity.setZero();  // only the velocity feedback is under test; no steady sag to integrate away
  const VecN offset = (VecN(5) << 0.05, -0.04, 0.03, 0.1, -0.1).finished();
  const double corrected = hold_and_settle(VirtualFeedback::Dissipative, offset, 3.0);
  const double printed = hold_and_settle(VirtualFeedback::AsPrinted, offset, 3.0);
  EXPECT_LT(corrected, 0.01 * offset.norm());
  EXPECT_GT(printed, 10.0 * offset.norm());  // grows (or leaves the finite numbers)
}

TEST_F(ControllerLoop, BlendingRemovesTheTorqueJumpAtContact) {
  // The master moves the virtual tip slowly into a plane; compare the largest tick-to-tick change
  // of the master torque with and without the blend.
  auto largest_jump = [&](double switch_time) {
    RobotData d(master);
    update_kinematics(master, d, home, VecN::Zero(5));
    Scene scene;
    scene.rigid =
        ImplicitSurface{SurfacePrimitive::plane(d.tip.translation() - Eigen::Vector3d(0, 0, 0.002), {0, 0, 1})};
    TeleoperationGains gains = thesis_holonomic_gains(5);
    gains.switch_time_s = switch_time;
    Teleoperation tele(master, virt, scene, gains, 0.002, 4);
    tele.reset(home, VecN::Zero(5));
    // Joint 3 turns so the tip goes down at about 2 cm/s; the hand presses 1 N.
    VecN dq = VecN::Zero(5);
    dq[2] = -0.1;
    TickInput in{home, dq, Wrench::Zero()};
    in.wrench_h[2] = -1.0;
    VecN previous = tele.step(in).tau_m;
    double worst = 0;
    for (int k = 1; k < 300; ++k) {
      in.q_m += 0.002 * dq;
      const VecN tau = tele.step(in).tau_m;
      worst = std::max(worst, (tau - previous).norm());
      previous = tau;
    }
    EXPECT_EQ(tele.world().report().mode, ContactMode::Holonomic);
    return worst;
  };
  const double blended = largest_jump(0.02), abrupt = largest_jump(1e-9);
  EXPECT_LT(blended, 0.3 * abrupt);
}

}  // namespace
}  // namespace needle::haptics
