#include "haptics/sim/hand_port.hpp"

#include "haptics/model/dynamics.hpp"

namespace needle::haptics {

double world_stored_energy(const Scenario& sc, const MasterPlant& plant, const Teleoperation& tele) {
  return kinetic_energy(plant.data()) + potential_energy(sc.master, plant.data()) + tele.stored_energy(plant.data());
}

}  // namespace needle::haptics
