// The master device's force limit: its motors on the first `actuated_joints` joints only, their
// torques scaled down together when they exceed what the motors can give. The controller commands
// within it (so that what it counts as given is what the device applies) and the simulated device
// (haptics/sim/master_plant.hpp) applies it. docs/HAPTICS.md, "Device".
//
// The limit is stated as a tip force at one pose: 3.3 N, the "maximum exertable force at nominal
// position" of the Geomagic Touch specification sheet (3D Systems). What bounds a device's force is
// its motors' torques (their amplifiers' current), whatever the pose, so the limit holds in joint
// space: the actuated torques τ_a may make at most F_max at the tip at the nominal pose,
//   ‖F_nom(τ_a)‖ ≤ F_max,  F_nom = J_a,nomᵀ⁺ τ_a  (J_a,nom: the tip's linear Jacobian's actuated columns there).
// At another pose the same torques make another force, as they do on the device. A tip-force limit
// through the present Jacobian would divide by a vanishing singular value near a singular pose (the
// arm stretched) and scale the weight compensation there to nothing, dropping the arm on the hand.
#pragma once

#include <array>

#include "haptics/model/robot_model.hpp"
#include "haptics/model/types.hpp"

namespace needle::haptics {

struct DeviceParams {
  double force_limit_N = 3.3;
  int actuated_joints = 3;
  // The pose at which force_limit_N is the force at the tip, joint by joint (joints beyond the list
  // at 0). Design value: the shipped scenarios' start pose, at the centre of the Omni model's
  // workspace with the forearm about square to the upper arm; the specification names its nominal
  // position without the angles.
  std::array<double, kMaxDof> nominal_pose_rad = {0.0, 1.0, -1.6, 0.0, 0.5, 0.0};
};

// The limit made ready for the tick: F_nom = force_per_torque τ_a.
struct DeviceLimit {
  Eigen::Matrix<double, 3, Eigen::Dynamic, 0, 3, kMaxDof> force_per_torque;  // J_a,nomᵀ⁺
  double force_limit_N = 0.0;
  int actuated_joints = 0;
};

// (model, device) => the limit: the tip's Jacobian at the nominal pose, its actuated columns'
// transpose pseudo-inverted (least squares when they are not square). Allocates; once per device.
DeviceLimit device_limit(const RobotModel& model, const DeviceParams& device);

// (limit; τ) => (τ: the unactuated joints zero, the actuated ones times κ = min(1, F_max / ‖F_nom(τ_a)‖));
// returns κ (1: within the limit). Allocation-free.
double limit_to_device(const DeviceLimit& limit, VecN& tau);

// (limit, τ, h) => the largest β ≥ 0 with ‖F_nom(τ_a − β h_a)‖ ≤ F_max, for a τ within the limit:
// how much of the torque h may be taken off τ before the motors run out. Allocation-free.
double room_within_limit(const DeviceLimit& limit, const VecN& tau, const VecN& h);

}  // namespace needle::haptics
