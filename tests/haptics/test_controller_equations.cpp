// Each equation group of the controller (haptics/control/teleoperation_terms.hpp) and the
// task-space coupling (task_space_coupling.hpp) on its own, against a case small enough to
// compute by hand; the arithmetic is in the comments.
// docs/CONTROLLER.md maps equation -> function -> test.
#include <gtest/gtest.h>

#include <cmath>

#include "haptics/control/task_space_coupling.hpp"
#include "haptics/control/teleoperation_terms.hpp"
#include "haptics/model/kinematics.hpp"
#include "robot_fixtures.hpp"

namespace needle::haptics {
namespace {

VecN vec(std::initializer_list<double> values) {
  VecN v(static_cast<Eigen::Index>(values.size()));
  Eigen::Index i = 0;
  for (double x : values) v[i++] = x;
  return v;
}

// The diagonal gains of one robot, two joints; the tracking gains do not enter these terms.
RobotGains gains(const VecN& Ka, const VecN& Kp) { return {Ka, Kp, VecN::Zero(2), VecN::Zero(2), VecN::Zero(2), 0.0}; }

TEST(ControllerEquations, ContactBlendRampsInAtEachNewContactAndOutAfterIt) {
  ContactBlend b;
  ForceErrorIntegrals e;
  auto dirty = [&e] {
    e.momentum_h.setConstant(1.0);
    e.momentum_v.setConstant(1.0);
    e.lambda.setConstant(1.0);
  };
  const double rate = 0.25;  // T / switch time, e.g. 2 ms / 8 ms
  advance_contact_blend(false, false, false, rate, b, e);
  EXPECT_EQ(b.any(), 0.0);
  dirty();
  advance_contact_blend(true, false, false, rate, b, e);  // new rigid contact: its integrals restart
  EXPECT_EQ(b.rigid, 0.25);
  EXPECT_EQ(e.momentum_h.norm() + e.momentum_v.norm(), 0.0);
  EXPECT_EQ(e.lambda[0], 1.0);                     // the tissue's are not touched
  for (double expected : {0.5, 0.75, 1.0, 1.0}) {  // clamped at 1
    dirty();
    advance_contact_blend(true, false, false, rate, b, e);
    EXPECT_EQ(b.rigid, expected);
    EXPECT_EQ(e.momentum_h[0], 1.0);  // not a new contact
  }
  for (double expected : {0.75, 0.5, 0.25, 0.0}) {  // out of contact the terms ramp out
    advance_contact_blend(false, false, false, rate, b, e);
    EXPECT_EQ(b.rigid, expected);
  }
  // Touching again before the weight reached 0 is the same contact; after, a new one.
  b.rigid = 0.25;
  dirty();
  advance_contact_blend(true, false, false, rate, b, e);
  EXPECT_EQ(e.momentum_v[0], 1.0);
  // Two contacts at once (bone reached in the tissue): each its own weight; the tissue's is new.
  dirty();
  advance_contact_blend(true, true, false, rate, b, e);
  EXPECT_EQ(b.rigid, 0.75);
  EXPECT_EQ(b.tissue, 0.25);
  EXPECT_EQ(e.lambda.norm(), 0.0);
  EXPECT_EQ(e.momentum_h[0], 1.0);
  advance_contact_blend(false, true, true, rate, b, e);
  EXPECT_EQ(b.rigid, 0.5);
  EXPECT_EQ(b.tissue, 0.5);
  EXPECT_EQ(b.axial, 0.25);
  EXPECT_EQ(b.any(), 0.5);
}

TEST(ControllerEquations, WrenchFilterIsAFirstOrderLowPass) {
  // 2π f T = ln 2, so each tick closes 1 − e^{−ln 2} = half of the gap to the input.
  const double T = 1e-3, f = std::log(2.0) / (2.0 * M_PI * T);
  Wrench sensed;
  sensed << 2, 0, 0, 0, 0, -4;
  Wrench filtered = Wrench::Zero();
  filter_wrench(sensed, f, T, filtered);
  EXPECT_NEAR(filtered[0], 1.0, 1e-12);
  EXPECT_NEAR(filtered[5], -2.0, 1e-12);
  filter_wrench(sensed, f, T, filtered);
  EXPECT_NEAR(filtered[0], 1.5, 1e-12);
  EXPECT_NEAR(filtered[5], -3.0, 1e-12);
  EXPECT_EQ(filtered[1], 0.0);
}

TEST(ControllerEquations, MasterFreeMotionTorqueIs313AsPrinted) {
  VecN tau;
  master_free_motion_torque(gains(vec({0.1, 0.2}), vec({0.5, 1.0})), vec({1, -2}), vec({4, 3}), tau);
  // −K_a q̇ − K_p s_a = (−0.1·1 − 0.5·4, −0.2·(−2) − 1·3) = (−2.1, −2.6).
  EXPECT_NEAR(tau[0], -2.1, 1e-15);
  EXPECT_NEAR(tau[1], -2.6, 1e-15);
}

TEST(ControllerEquations, VirtualFreeMotionTorqueIs314WithTheDissipativeSign) {
  const RobotGains g = gains(vec({0.2, 0.1}), vec({0.3, 0.5}));
  const VecN dq = vec({1, 2}), s_a = vec({3, -1});
  VecN tau0, B;
  virtual_free_motion_torque(g, VirtualFeedback::Dissipative, dq, s_a, tau0, B);
  // B = K_a + K_p = (0.5, 0.6); τ₀ = −K_p (s_a − q̇) = (−0.3·2, −0.5·(−3)) = (−0.6, 1.5);
  // τ₀ − B q̇ = (−1.1, 0.3) = −(K_a q̇ + K_p s_a) = −(0.2 + 0.9, 0.2 − 0.5).
  EXPECT_NEAR(B[0], 0.5, 1e-15);
  EXPECT_NEAR(B[1], 0.6, 1e-15);
  EXPECT_NEAR(tau0[0], -0.6, 1e-15);
  EXPECT_NEAR(tau0[1], 1.5, 1e-15);
  virtual_free_motion_torque(g, VirtualFeedback::AsPrinted, dq, s_a, tau0, B);  // +(K_a q̇ + K_p s_a)
  const VecN tau = tau0 - B.cwiseProduct(dq);
  EXPECT_NEAR(tau[0], 1.1, 1e-15);
  EXPECT_NEAR(tau[1], -0.3, 1e-15);
}

TEST(ControllerEquations, MasterDynamicsCancellationIsCoriolisDampingAndGravity) {
  using namespace test::planar;
  RobotModel model = arm();
  model.joints[0].damping = 0.05;
  model.joints[1].damping = 0.02;
  RobotData data(model);
  const double a = 0.3, b = 0.8, da = 0.7, db = -1.3;
  update_frames(model, data, vec({a, b}), vec({da, db}));
  VecN tau_m = vec({1, -1});
  master_dynamics_cancellation(model, data, 0.5, false, tau_m);
  // Closed forms of the planar arm: h = −m₂ l₁ l_c2 sin b, C q̇ = (h ḃ² + 2h ȧ ḃ, −h ȧ²),
  // g = ((m₁ l_c1 + m₂ l₁) g₀ cos a + m₂ l_c2 g₀ cos(a + b), m₂ l_c2 g₀ cos(a + b)), D q̇ = (0.05 ȧ, 0.02 ḃ);
  // τ_m = (1, −1) + 0.5 (C q̇ + D q̇ + g).
  const double h = -m2 * l1 * lc2 * std::sin(b), g2 = m2 * lc2 * g0 * std::cos(a + b);
  const double g1 = (m1 * lc1 + m2 * l1) * g0 * std::cos(a) + g2;
  const double y1 = h * db * db + 2 * h * da * db + 0.05 * da + g1;
  const double y2 = -h * da * da + 0.02 * db + g2;
  EXPECT_NEAR(tau_m[0], 1 + 0.5 * y1, 1e-12);
  EXPECT_NEAR(tau_m[1], -1 + 0.5 * y2, 1e-12);
  // The tool law: gravity whatever w, the rest blended: τ_m = (1, −1) + g + 0.5 (C q̇ + D q̇).
  tau_m = vec({1, -1});
  master_dynamics_cancellation(model, data, 0.5, true, tau_m);
  EXPECT_NEAR(tau_m[0], 1 + g1 + 0.5 * (y1 - g1), 1e-12);
  EXPECT_NEAR(tau_m[1], -1 + g2 + 0.5 * (y2 - g2), 1e-12);
  tau_m = vec({1, -1});
  master_dynamics_cancellation(model, data, 0.0, true, tau_m);  // free motion: gravity alone
  EXPECT_NEAR(tau_m[0], 1 + g1, 1e-12);
  EXPECT_NEAR(tau_m[1], -1 + g2, 1e-12);
}

TEST(ControllerEquations, ToolWeightPressesTheStylusDownAndIsTakenOutOfTheHandsWrench) {
  // Linear rows of J_m: x = q₁, z = 2 q₂ (+ angular 7s, which must not enter).
  Mat6N J_m = Mat6N::Constant(6, 2, 7.0);
  J_m.topRows<3>() << 1, 0, 0, 0, 0, 2;
  Wrench wrench_h, net;
  wrench_h << 0.1, 0, 0.147, 0.01, 0, 0;  // the hand holds a 15 g tool up and pushes 0.1 N along x
  VecN tau_m = vec({1, 1});
  tool_weight(0.015, Eigen::Vector3d(0, 0, -9.8), J_m, wrench_h, tau_m, net);
  // m g = (0, 0, −0.147): τ_m += J_mᵀ m g = (0, −0.294); w_net = (0.1, 0, 0, 0.01, 0, 0).
  EXPECT_NEAR(tau_m[0], 1.0, 1e-15);
  EXPECT_NEAR(tau_m[1], 1.0 - 0.294, 1e-15);
  EXPECT_NEAR(net[0], 0.1, 1e-15);
  EXPECT_NEAR(net[2], 0.0, 1e-15);
  EXPECT_EQ(net[3], 0.01);
}

TEST(ControllerEquations, RigidForceErrorsIntegrateTheNormalForceDifference) {
  const Eigen::Vector3d normal(0.6, 0, 0.8), force_v(-1.2, 0, -1.6);  // F_v = −2 n̂: the tool presses
  Wrench wrench_h;
  wrench_h << 1, 2, -3, 0.5, 0.5, 0.5;  // the hand's torque does not enter
  ForceErrorIntegrals e;
  Eigen::Vector3d force_h_normal;
  rigid_force_errors(normal, wrench_h, force_v, 0.5, 0.1, force_h_normal, e);
  // n̂ᵀF_h = 0.6 − 2.4 = −1.8, F_h,n = −1.8 n̂ = (−1.08, 0, −1.44); F_v − F_h,n = (−0.12, 0, −0.16);
  // T w = 0.05: Δp_v = (−0.006, 0, −0.008), Δp_h its opposite.
  EXPECT_TRUE(force_h_normal.isApprox(Eigen::Vector3d(-1.08, 0, -1.44), 1e-14));
  EXPECT_TRUE(e.momentum_v.isApprox(Eigen::Vector3d(-0.006, 0, -0.008), 1e-14));
  EXPECT_TRUE(e.momentum_h.isApprox(Eigen::Vector3d(0.006, 0, 0.008), 1e-14));
  rigid_force_errors(normal, wrench_h, force_v, 0.5, 0.1, force_h_normal, e);  // integrals accumulate
  EXPECT_TRUE(e.momentum_v.isApprox(Eigen::Vector3d(-0.012, 0, -0.016), 1e-14));
}

TEST(ControllerEquations, RigidForceTorquesAre320And321ForceTerms) {
  // Two joints; linear rows of J_v: x = q₁, y = q₂, z = q₁ + q₂; of J_m: x = 2 q₁, z = q₂. The
  // angular rows (7s) must not enter: forces only.
  Mat6N J_v = Mat6N::Constant(6, 2, 7.0), J_m = Mat6N::Constant(6, 2, 7.0);
  J_v.topRows<3>() << 1, 0, 0, 1, 1, 1;
  J_m.topRows<3>() << 2, 0, 0, 0, 0, 1;
  ForceErrorIntegrals e;
  e.momentum_v = Eigen::Vector3d(0, 0, 0.5);
  e.momentum_h = Eigen::Vector3d(0, 0, -1.0);
  VecN tau_v = vec({1, 1}), tau_m = vec({1, 1});
  rigid_force_torques(J_v, J_m, Eigen::Vector3d(0, 0, -3), Eigen::Vector3d(0.5, 0, -2), e, 2.0, 4.0, 1.0, 0.5, tau_v,
                      tau_m);
  // τ_v += 0.5 J_vᵀ (F_h,n − 2 Δp_v) = 0.5 J_vᵀ (0, 0, −4) = (−2, −2)  → (−1, −1).
  // τ_m −= 0.5 J_mᵀ (F_v − 4 Δp_h) = 0.5 J_mᵀ (0.5, 0, 2) = (0.5, 1) → (0.5, 0).
  EXPECT_NEAR(tau_v[0], -1.0, 1e-15);
  EXPECT_NEAR(tau_v[1], -1.0, 1e-15);
  EXPECT_NEAR(tau_m[0], 0.5, 1e-15);
  EXPECT_NEAR(tau_m[1], 0.0, 1e-15);
  // Force scale 0.4: the master's term is 0.4 times as large, the virtual's the same.
  tau_v = vec({1, 1}), tau_m = vec({1, 1});
  rigid_force_torques(J_v, J_m, Eigen::Vector3d(0, 0, -3), Eigen::Vector3d(0.5, 0, -2), e, 2.0, 4.0, 0.4, 0.5, tau_v,
                      tau_m);
  EXPECT_NEAR(tau_v[0], -1.0, 1e-15);
  EXPECT_NEAR(tau_m[0], 1 - 0.4 * 0.5, 1e-15);
  EXPECT_NEAR(tau_m[1], 1 - 0.4 * 1.0, 1e-15);
}

// Two constraint rows on three joints: A = [1 1 0; 0 1 1], A Aᵀ = [2 1; 1 2], (A Aᵀ)⁻¹ = [2 −1; −1 2] / 3.
MatKN two_rows() {
  MatKN A(2, 3);
  A << 1, 1, 0, 0, 1, 1;
  return A;
}

TEST(ControllerEquations, OperatorMultiplierIs324) {
  Mat6N J_m = Mat6N::Zero(6, 3);
  J_m.topRows<3>().setIdentity();
  J_m(5, 2) = 1.0;  // joint 3 also turns about z, so the hand's torque about z reaches it
  Wrench wrench_h;
  wrench_h << 1, 2, 2, 0, 0, 1;
  OperatorMultiplierScratch scratch;
  VecK lambda_m;
  operator_multiplier(two_rows(), J_m, wrench_h, scratch, lambda_m);
  // τ_h = J_mᵀ w_h = (1, 2, 3); A τ_h = (3, 5); λ_m = [2 −1; −1 2] (3, 5) / 3 = (1/3, 7/3).
  // (τ_h − Aᵀλ_m = (2/3, −2/3, 2/3) is orthogonal to A's rows: λ_m is the least-squares push.)
  ASSERT_EQ(lambda_m.size(), 2);
  EXPECT_NEAR(lambda_m[0], 1.0 / 3.0, 1e-15);
  EXPECT_NEAR(lambda_m[1], 7.0 / 3.0, 1e-15);
}

TEST(ControllerEquations, TissueForceErrorIs326) {
  ForceErrorIntegrals e;
  VecK lambda_m(2), lambda_v(2);
  lambda_m << 1, -2;
  lambda_v << -0.5, 1;
  tissue_force_error(lambda_m, lambda_v, 0.5, 0.1, e);
  // E += T w (λ_m + λ_v) = 0.05 (0.5, −1) = (0.025, −0.05), twice: (0.05, −0.1).
  EXPECT_NEAR(e.lambda[0], 0.025, 1e-15);
  EXPECT_NEAR(e.lambda[1], -0.05, 1e-15);
  tissue_force_error(lambda_m, lambda_v, 0.5, 0.1, e);
  EXPECT_NEAR(e.lambda[0], 0.05, 1e-15);
  EXPECT_NEAR(e.lambda[1], -0.1, 1e-15);
}

TEST(ControllerEquations, TissueForceTorquesAre327And328ForceTerms) {
  ForceErrorIntegrals e;
  e.lambda << 0.5, 0.5;
  VecK lambda_m(2), lambda_v(2);
  lambda_m << 1, 0;
  lambda_v << -1, 0;
  VecN tau_v = VecN::Zero(3), tau_m = VecN::Zero(3);
  tissue_force_torque_virtual(two_rows(), lambda_m, e, 2.0, 0.5, tau_v);
  tissue_force_torque_master(two_rows(), lambda_v, e, 4.0, 1.0, 0.5, tau_m);
  // τ_v += 0.5 Aᵀ (λ_m + 2E) = 0.5 Aᵀ (2, 1) = 0.5 (2, 3, 1) = (1, 1.5, 0.5).
  // τ_m += 0.5 Aᵀ (λ_v + 4E) = 0.5 Aᵀ (1, 2) = 0.5 (1, 3, 2) = (0.5, 1.5, 1).
  EXPECT_TRUE(tau_v.isApprox(vec({1, 1.5, 0.5}), 1e-15));
  EXPECT_TRUE(tau_m.isApprox(vec({0.5, 1.5, 1}), 1e-15));
  // Force scale 0.4 on the master's term only.
  tau_v.setZero(), tau_m.setZero();
  tissue_force_torque_virtual(two_rows(), lambda_m, e, 2.0, 0.5, tau_v);
  tissue_force_torque_master(two_rows(), lambda_v, e, 4.0, 0.4, 0.5, tau_m);
  EXPECT_TRUE(tau_v.isApprox(vec({1, 1.5, 0.5}), 1e-15));
  EXPECT_TRUE(tau_m.isApprox(vec({0.2, 0.6, 0.4}), 1e-15));
}

TEST(ControllerEquations, AxialForceTorquesFeedTheHandsPushToTheToolAndTheTissueToTheHand) {
  // Needle along x₅ = (0.6, 0, −0.8); linear rows of J_v: x = q₁, z = q₂; of J_m: x = 2 q₁, z = q₂.
  const Eigen::Vector3d axis(0.6, 0, -0.8);
  Mat6N J_v = Mat6N::Constant(6, 2, 7.0), J_m = Mat6N::Constant(6, 2, 7.0);
  J_v.topRows<3>() << 1, 0, 0, 0, 0, 1;
  J_m.topRows<3>() << 2, 0, 0, 0, 0, 1;
  Wrench wrench_h;
  wrench_h << 1, 5, -2, 3, 3, 3;  // the lateral y and the torque do not enter
  VecN tau_v = vec({0, 0}), tau_m = vec({0, 0});
  const double push = axial_force_torques(axis, wrench_h, 1.5, J_v, J_m, 0.4, 0.5, tau_v, tau_m);
  // F_h,a = x₅ᵀ f = 0.6 + 1.6 = 2.2; τ_v += 0.5 · 2.2 J_vᵀ x₅ = 1.1 (0.6, −0.8) = (0.66, −0.88).
  // τ_m −= 0.5 · 0.4 · 1.5 J_mᵀ x₅ = 0.3 (1.2, −0.8) = (0.36, −0.24)  → (−0.36, 0.24).
  EXPECT_NEAR(push, 2.2, 1e-15);
  EXPECT_TRUE(tau_v.isApprox(vec({0.66, -0.88}), 1e-14));
  EXPECT_TRUE(tau_m.isApprox(vec({-0.36, 0.24}), 1e-14));
}

TEST(ControllerEquations, AxialAndLateralDampingOpposeTheMastersMotionAlongAndAcrossTheNeedle) {
  // Master tip velocity ẋ = J_lin q̇ with J_lin rows x = 2 q₁, z = q₂; q̇ = (0.5, −1): ẋ = (1, 0, −1).
  Mat6N J_m = Mat6N::Constant(6, 2, 7.0);
  J_m.topRows<3>() << 2, 0, 0, 0, 0, 1;
  const VecN dq = vec({0.5, -1});
  const Eigen::Vector3d axis(0.6, 0, -0.8);
  // Along x₅: v = x₅ᵀẋ = 1.4; F = −w b v x₅ = −0.5 · 30 · 1.4 (0.6, 0, −0.8) = (−12.6, 0, 16.8);
  // τ = J_linᵀ F = (−25.2, 16.8).
  VecN tau = vec({0, 0});
  axial_damping_torque(axis, J_m, dq, 30.0, 0.5, tau);
  EXPECT_TRUE(tau.isApprox(vec({-25.2, 16.8}), 1e-14));
  EXPECT_LT(tau.dot(dq), 0.0);  // dissipative: power τᵀq̇ = Fᵀẋ < 0
  // Across it (y₅, z₅ spanning the plane ⊥ x₅): F = −w b (ẋ − x₅x₅ᵀẋ) = −5 ((1, 0, −1) − 1.4 x₅) = −5 (0.16, 0, 0.12).
  Eigen::Matrix3d frame;
  frame.col(0) = axis;
  frame.col(1) = Eigen::Vector3d(0.8, 0, 0.6);
  frame.col(2) = Eigen::Vector3d(0, 1, 0);
  tau = vec({0, 0});
  lateral_damping_torque(frame, J_m, dq, 10.0, 0.5, tau);
  EXPECT_TRUE(tau.isApprox(vec({-1.6, -0.6}), 1e-14));
  EXPECT_LT(tau.dot(dq), 0.0);
}

// The lateral spring's torque is the gradient of its energy U(q) = ½ w K |P (x_m(q) − x_v)|² with
// the needle's line held still: τ = −∂U/∂q, checked by central differences on the planar arm.
TEST(ControllerEquations, LateralSpringTorqueIsTheGradientOfItsEnergyAcrossTheNeedle) {
  const RobotModel model = test::planar::arm();
  RobotData data(model);
  Eigen::Matrix3d frame;  // needle along (0.6, 0, −0.8)
  frame.col(0) = Eigen::Vector3d(0.6, 0, -0.8);
  frame.col(1) = Eigen::Vector3d(0.8, 0, 0.6);
  frame.col(2) = Eigen::Vector3d(0, 1, 0);
  const Eigen::Vector3d x_v(0.05, 0.02, -0.01);
  const double K = 300.0, w = 0.7;
  auto energy = [&](const VecN& q) {
    update_kinematics(model, data, q, VecN::Zero(2));
    return 0.5 * w * K * lateral_offset(frame, data.tip.translation(), x_v).squaredNorm();
  };
  const VecN q = vec({0.3, -0.5});
  update_kinematics(model, data, q, VecN::Zero(2));
  VecN tau = vec({0, 0});
  lateral_spring_torque(frame, data.tip.translation(), x_v, data.J, K, w, tau);
  const double h = 1e-6;
  for (int i = 0; i < 2; ++i) {
    VecN plus = q, minus = q;
    plus[i] += h, minus[i] -= h;
    EXPECT_NEAR(tau[i], -(energy(plus) - energy(minus)) / (2 * h), 1e-6 * (1.0 + std::abs(tau[i]))) << "joint " << i;
  }
  // Along the needle the spring is slack: P x₅ = 0.
  EXPECT_NEAR(lateral_offset(frame, x_v + 0.03 * frame.col(0), x_v).norm(), 0.0, 1e-15);
}

// The spring along the needle between the two tips: the virtual robot's torque is minus the gradient
// of E = ½ w K (x₅ᵀ(x_m − x_v))² in its joints, the master's s times minus the gradient in its own
// (the hand feels the scene's force scaled), both by central differences; across the needle it is slack.
TEST(ControllerEquations, AxialSpringTorquesAreTheGradientsOfItsEnergyAlongTheNeedle) {
  const RobotModel model = test::planar::arm();
  RobotData master(model), virt(model);
  const Eigen::Vector3d axis(0.6, 0.8, 0.0);  // in the arm's plane
  const double K = 3000.0, s = 0.35, w = 0.7;
  const VecN q_m = vec({0.3, -0.5}), q_v = vec({0.1, -0.1});
  auto energy = [&](const VecN& qm, const VecN& qv) {
    update_kinematics(model, master, qm, VecN::Zero(2));
    update_kinematics(model, virt, qv, VecN::Zero(2));
    const double along = axis.dot(master.tip.translation() - virt.tip.translation());
    return 0.5 * w * K * along * along;
  };
  update_kinematics(model, master, q_m, VecN::Zero(2));
  update_kinematics(model, virt, q_v, VecN::Zero(2));
  VecN tau_m = vec({0, 0}), tau_v = vec({0, 0});
  const double force = axial_spring_torques(axis, master.tip.translation(), virt.tip.translation(), virt.J, master.J, K,
                                            s, w, tau_v, tau_m);
  EXPECT_NEAR(force, w * K * axis.dot(master.tip.translation() - virt.tip.translation()), 1e-12);
  EXPECT_GT(std::abs(force), 1.0);  // the configuration stretches the spring
  const double h = 1e-6;
  for (int i = 0; i < 2; ++i) {
    VecN plus = q_m, minus = q_m;
    plus[i] += h, minus[i] -= h;
    EXPECT_NEAR(tau_m[i], -s * (energy(plus, q_v) - energy(minus, q_v)) / (2 * h), 1e-6 * (1.0 + std::abs(tau_m[i])))
        << "master joint " << i;
    plus = q_v, minus = q_v;
    plus[i] += h, minus[i] -= h;
    EXPECT_NEAR(tau_v[i], -(energy(q_m, plus) - energy(q_m, minus)) / (2 * h), 1e-6 * (1.0 + std::abs(tau_v[i])))
        << "virtual joint " << i;
  }
  // Across the needle it is slack: tips apart only across x₅ pull nothing.
  VecN none_m = vec({0, 0}), none_v = vec({0, 0});
  const Eigen::Vector3d across(0.8, -0.6, 0.0);
  EXPECT_NEAR(axial_spring_torques(axis, virt.tip.translation() + 0.02 * across, virt.tip.translation(), virt.J,
                                   master.J, K, s, w, none_v, none_m),
              0.0, 1e-12);
}

// The spring along the needle is held at half the explicit limit of the virtual tip's mass along it,
// 2 / (T² x₅ᵀ J (H + hB)⁻¹ Jᵀ x₅): closed form for two joints each moving the tip along one axis.
TEST(ControllerEquations, AxialSpringStiffnessIsHeldUnderTheTicksLimit) {
  Mat6N J = Mat6N::Zero(6, 2);
  J(0, 0) = 2.0;  // joint 1 moves the tip along x at 2 m/rad
  J(1, 1) = 1.0;  // joint 2 along y
  MatN H = MatN::Zero(2, 2);
  H.diagonal() << 0.2, 0.5;
  const VecN B = vec({0.4, 0.0});
  const double h = 0.001;
  AxialSpringScratch scratch;
  // Along x the tip's mass is (0.2 + 0.001 * 0.4) / 2² = 0.0501 kg.
  const double m = (0.2 + h * 0.4) / 4.0;
  EXPECT_NEAR(axial_spring_stiffness(1e6, H, B, h, J, Eigen::Vector3d::UnitX(), 0.016, scratch),
              2.0 * m / (0.016 * 0.016), 1e-9);
  EXPECT_EQ(axial_spring_stiffness(3000.0, H, B, h, J, Eigen::Vector3d::UnitX(), 0.002, scratch),
            3000.0);  // limit 25050
  // Along y: 0.5 kg; along (x + y)/√2 the inverse masses add: (1/m_x + 1/m_y) / 2.
  EXPECT_NEAR(axial_spring_stiffness(1e6, H, B, h, J, Eigen::Vector3d::UnitY(), 0.016, scratch),
              2.0 * 0.5 / (0.016 * 0.016), 1e-9);
  const double inverse_mass = (1.0 / m + 1.0 / 0.5) / 2.0;
  EXPECT_NEAR(axial_spring_stiffness(1e6, H, B, h, J, Eigen::Vector3d(1, 1, 0).normalized(), 0.016, scratch),
              2.0 / (0.016 * 0.016 * inverse_mass), 1e-6);
  // A tip that cannot move along the axis bounds nothing.
  EXPECT_EQ(axial_spring_stiffness(3000.0, H, B, h, J, Eigen::Vector3d::UnitZ(), 0.016, scratch), 3000.0);
}

TEST(ControllerEquations, TaskSpaceCouplingIsASpringOnTheTipAndOneOnTheDirection) {
  const RobotModel model = test::planar::arm();
  RobotData data(model);
  data.tip = Eigen::Isometry3d::Identity();  // needle axis x₅ = x
  data.tip.translation() = Eigen::Vector3d(0.1, 0, 0);
  data.J = Mat6N::Zero(6, 2);
  data.J.col(0) << 1, 0, 0, 0, 0, 1;  // joint 1 moves the tip along x and turns it about z
  data.J.col(1) << 0, 2, 0, 0, 0, 1;  // joint 2 moves it along y at 2 m/rad and turns it about z
  data.g = vec({1, -1});
  TaskCoupling c;
  c.stiffness_n_per_m = 300.0;
  c.orientation_stiffness_nm_per_rad = 0.5;
  Eigen::Vector3d force;
  VecN tau;
  task_space_coupling(c, data, Eigen::Vector3d(0.2, 0.1, 0), Eigen::Vector3d::UnitY(), force, tau);
  // F = 300 (0.1, 0.1, 0) = (30, 30, 0); the direction spring 0.5 x × y = (0, 0, 0.5);
  // τ = Jᵀ [F; M] + g = (30 + 0.5 + 1, 2·30 + 0.5 − 1) = (31.5, 59.5).
  EXPECT_TRUE(force.isApprox(Eigen::Vector3d(30, 30, 0), 1e-14));
  EXPECT_NEAR(tau[0], 31.5, 1e-12);
  EXPECT_NEAR(tau[1], 59.5, 1e-12);
}

}  // namespace
}  // namespace needle::haptics
