// Per-robot state and scratch space, sized once from a model; the algorithms in kinematics.hpp,
// dynamics.hpp and regressor.hpp fill it without allocating.
#pragma once

#include <Eigen/Geometry>
#include <array>

#include "haptics/model/robot_model.hpp"
#include "haptics/model/small_cholesky.hpp"

namespace needle::haptics {

// Inertial parameters: per joint body (m, m·c (3), inertia about the joint-frame origin
// xx xy xz yy yz zz), all in the joint frame, then one viscous coefficient per joint (2.22).
inline constexpr int kParamsPerBody = 10;
inline constexpr int kMaxParams = (kParamsPerBody + 1) * kMaxDof;
using ParamVec = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, kMaxParams, 1>;
using RegressorMat = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, kMaxDof, kMaxParams>;

struct RobotData {
  explicit RobotData(const RobotModel& model);

  int n;
  VecN q, dq;

  // Filled by update_kinematics, all in the base frame.
  std::array<Eigen::Isometry3d, kMaxDof> frame;  // joint frames after rotation
  std::array<Eigen::Vector3d, kMaxDof> axis;     // joint axes z_i
  std::array<Eigen::Vector3d, kMaxDof> origin;   // joint-frame origins p_i (on the axes)
  std::array<Eigen::Vector3d, kMaxDof> origin_velocity;
  std::array<Eigen::Vector3d, kMaxDof> omega;  // angular velocity of body i
  std::array<Eigen::Vector3d, kMaxDof> com;    // centre of mass of body i
  std::array<Mat6N, kMaxDof> J_com, Jdot_com;  // geometric Jacobians of the centres of mass
  Eigen::Isometry3d tip;
  Eigen::Matrix<double, 6, 1> tip_twist;  // [ṗ; ω]
  Mat6N J, Jdot;                          // tip geometric Jacobian [linear; angular] and its rate

  // Filled by update_dynamics (H, C, g, bias) or update_tick_dynamics (H, bias, inertia_world).
  std::array<Eigen::Matrix3d, kMaxDof> inertia_world;  // body inertia about its centre of mass, base axes
  MatN H, C;
  VecN g;
  VecN bias;  // C q̇ + g

  // Scratch.
  SmallCholesky<kMaxDof> llt;  // of H (forward_dynamics) or of what the caller factorized
  std::array<Eigen::Vector3d, kMaxDof> omega_dot, accel, force, moment;
  ParamVec unit_params;
};

}  // namespace needle::haptics
