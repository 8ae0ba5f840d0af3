// The master device's force limit: its motors on the first `actuated_joints` joints only, their
// torques scaled down together when the force they make at the tip would exceed the limit. The
// controller commands within it (so that what it counts as given is what the device applies) and the
// simulated device (haptics/sim/master_plant.hpp) applies it. Default: 3.3 N, the "maximum exertable
// force at nominal position" of the Geomagic Touch specification sheet (3D Systems).
#pragma once

#include "haptics/model/types.hpp"

namespace needle::haptics {

struct DeviceParams {
  double force_limit_N = 3.3;
  int actuated_joints = 3;
};

// (J, device; τ) => (τ: the unactuated joints zero, the actuated ones times κ = min(1, F_max / ‖F‖),
// F the tip force they make, J_aᵀF = τ_a in the least-squares sense when J_a is singular or not
// square); returns whether κ < 1. Allocation-free.
bool limit_to_device(const Mat6N& J, const DeviceParams& device, VecN& tau);

}  // namespace needle::haptics
