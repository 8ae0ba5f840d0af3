// Joint-space dynamics (2.20)/(2.21): H(q) q̈ + C(q, q̇) q̇ + D q̇ + g(q) = τ, from the
// centre-of-mass Jacobians. C is the factorization for which Ḣ − 2C is skew-symmetric.
#pragma once

#include "haptics/model/robot_data.hpp"

namespace needle::haptics {

// H, C, g and bias = C q̇ + g at the state of the last update_kinematics. Allocation-free.
void update_dynamics(const RobotModel& model, RobotData& data);
// bias = C q̇ + g (Newton-Euler at q̈ = 0, with the model's inertias) and inertia_world, after
// update_frames; the servo tick's master needs no more.
void update_bias(const RobotModel& model, RobotData& data);
// g = g(q) alone (Newton-Euler at q̇ = q̈ = 0), after update_frames: the torque that holds the robot
// still against its weight. For the controller's gravity compensation.
void update_gravity(const RobotModel& model, RobotData& data);
// update_bias, then H (composite rigid bodies), after update_frames: the servo tick's cheaper path;
// C and g are left as they were.
void update_tick_dynamics(const RobotModel& model, RobotData& data);

// q̈ = H⁻¹ (τ − C q̇ − D q̇ − g) = H⁻¹ (τ − bias − D q̇); τ includes every external torque.
// Needs update_dynamics or update_tick_dynamics.
void forward_dynamics(const RobotModel& model, RobotData& data, const VecN& tau, VecN& ddq);

double kinetic_energy(const RobotData& data);                             // ½ q̇ᵀ H q̇, needs update_dynamics
double potential_energy(const RobotModel& model, const RobotData& data);  // −Σ mᵢ gᵀ cᵢ

}  // namespace needle::haptics
