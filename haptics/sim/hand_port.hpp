// Passivity at the hand ("the virtual world never does net positive work on the hand"):
// what the world behind the hand's port (the sensor between hand and stylus) holds and may give
// back. The hand's work on the stylus minus the change of this energy is what the world has
// dissipated; docs/CONTROLLER.md, "Passivity at the hand", states the terms and what is left.
#pragma once

#include "haptics/control/teleoperation.hpp"
#include "haptics/sim/master_plant.hpp"
#include "haptics/sim/scenario.hpp"

namespace needle::haptics {

// (scenario, master plant, teleoperation) => the energy stored behind the hand's port, J: the
// device's own ½q̇_mᵀH_mq̇_m + V_m(q_m) (the hand's mass is the hand's) and what the world behind the
// device's actuators holds (Teleoperation::stored_energy: under the tool law the gravity compensation's
// −V_m, which cancels V_m, the rendered tool's weight −m gᵀx_m, the lateral and axial springs; the
// virtual robot ½q̇_vᵀH_vq̇_v + V_v and the tissue's tented surface and stick, k₁d²/2 + k₂d³/3 +
// F_g²/2k_g, in the hand's units).
double world_stored_energy(const Scenario& scenario, const MasterPlant& plant, const Teleoperation& tele);

}  // namespace needle::haptics
