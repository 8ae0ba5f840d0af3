#include "haptics/sim/hand_port.hpp"

#include "haptics/model/dynamics.hpp"

namespace needle::haptics {

double world_stored_energy(const Scenario& sc, const MasterPlant& plant, const VirtualWorld& world) {
  const bool tool = sc.gains.law == ControlLaw::Tool;
  double e = kinetic_energy(plant.data()) + world.energy() + tissue_stored_energy(world.scene().tissue, world.tissue());
  if (tool) e -= sc.gains.tool.mass_kg * sc.master.gravity.dot(plant.data().tip.translation());
  else e += potential_energy(sc.master, plant.data());
  return e;
}

}  // namespace needle::haptics
