// Tracking terms (3.8)-(3.12) against hand-computed values, and the thesis gains as defaults.
#include <gtest/gtest.h>

#include "haptics/control/tracking.hpp"

namespace needle::haptics {
namespace {

TEST(ControllerTracking, SlidingVariablesAndSigmaFollowTheCorrectedEquations) {
  RobotGains g{VecN::Constant(2, 0.1), VecN::Constant(2, 0.2), VecN::Constant(2, 2.0),
               VecN::Constant(2, 0.5), VecN::Constant(2, 3.0), 0.0};
  TrackingState state;
  state.reset(2);
  VecN qi(2), dqi(2), qj(2), dqj(2);
  qi << 1.0, -1.0;
  dqi << 0.5, 0.0;
  qj << 0.5, -1.5;
  dqj << 0.0, 0.25;
  TrackingTerms t;
  state.update(g, qi, dqi, qj, dqj, 0.01, t);
  // s = q̇_i − q̇_j + Λ(q_i − q_j) = (0.5 + 1.0, −0.25 + 1.0); σ was 0, so s_a = s.
  EXPECT_NEAR(t.s[0], 1.5, 1e-15);
  EXPECT_NEAR(t.s[1], 0.75, 1e-15);
  EXPECT_EQ(t.s_a, t.s);
  // σ = T (K_β s + sign s) = 0.01 (0.75 + 1, 0.375 + 1).
  EXPECT_NEAR(state.sigma()[0], 0.0175, 1e-15);
  EXPECT_NEAR(state.sigma()[1], 0.01375, 1e-15);
  state.update(g, qi, dqi, qj, dqj, 0.01, t);
  EXPECT_NEAR(t.s_a[0], 1.5 + 3.0 * 0.0175, 1e-15);  // s_a = s + K_γ σ
}

TEST(ControllerTracking, ThesisGainsAreTheDefaults) {
  const TeleoperationGains h = thesis_holonomic_gains(5), nh = thesis_nonholonomic_gains(5);
  EXPECT_DOUBLE_EQ(h.master.Ka[0], 0.055);
  EXPECT_DOUBLE_EQ(h.master.Kp[0], 0.0055);
  EXPECT_DOUBLE_EQ(h.master.Kf, 10.05);
  EXPECT_DOUBLE_EQ(h.master.Lambda[4], 0.25);
  EXPECT_DOUBLE_EQ(h.virt.Kp[2], 0.2);
  EXPECT_DOUBLE_EQ(h.virt.Kp[3], 0.1);
  EXPECT_DOUBLE_EQ(h.virt.Lambda[0], 20.0);
  EXPECT_DOUBLE_EQ(h.gpm.alpha, 0.02);
  EXPECT_DOUBLE_EQ(nh.master.Kp[0], 0.055);
  EXPECT_DOUBLE_EQ(nh.master.Kf, 0.01);
  EXPECT_DOUBLE_EQ(nh.virt.Kf, 2.0);
  EXPECT_EQ(h.virtual_feedback, VirtualFeedback::Dissipative);
}

}  // namespace
}  // namespace needle::haptics
