// Passivity at the hand (issue 12: "the virtual world never does net positive work on the hand"):
// what the world behind the hand's port (the sensor between hand and stylus) holds and may give
// back. The hand's work on the stylus minus the change of this energy is what the world has
// dissipated; docs/CONTROLLER.md, "Passivity at the hand", states the terms and what is left.
#pragma once

#include "haptics/control/teleoperation.hpp"
#include "haptics/sim/master_plant.hpp"
#include "haptics/sim/scenario.hpp"

namespace needle::haptics {

// (scenario, master plant, teleoperation) => the energy stored behind the hand's port, J:
//   ½q̇_mᵀH_mq̇_m                 the device's own kinetic energy (the hand's mass is the hand's);
//   V_m(q_m)                      the device's weight, unless the tool law compensates it (g_m in τ_m);
//   −m gᵀx_m                      the rendered tool's weight (tool law);
//   ½q̇_vᵀH_vq̇_v + V_v             the virtual robot (weightless under the tool law);
//   k₁d²/2 + k₂d³/3 + F_g²/2k_g   the tissue's tented surface and stick (tissue_stored_energy);
//   ½ w K |P (x_m − x_v)|²        the master's lateral spring to the needle's line (tool law);
//   ½ w K_a (x₅ᵀ(x_m − x_v))²      the spring along the needle between the tips (tool law).
double world_stored_energy(const Scenario& scenario, const MasterPlant& plant, const Teleoperation& tele);

}  // namespace needle::haptics
