#include "haptics/sim/hand_port.hpp"

#include "haptics/control/teleoperation_terms.hpp"
#include "haptics/model/dynamics.hpp"

namespace needle::haptics {

double world_stored_energy(const Scenario& sc, const MasterPlant& plant, const Teleoperation& tele) {
  const VirtualWorld& world = tele.world();
  const bool tool = sc.gains.law == ControlLaw::Tool;
  double e = kinetic_energy(plant.data()) + world.energy() + tissue_stored_energy(world.scene().tissue, world.tissue());
  if (tool) {
    e -= sc.gains.tool.mass_kg * sc.master.gravity.dot(plant.data().tip.translation());
    const Eigen::Isometry3d& tip_v = world.data().tip;
    const Eigen::Vector3d offset = lateral_offset(tip_v.linear(), plant.data().tip.translation(), tip_v.translation());
    e += 0.5 * tele.blend().tissue * sc.gains.lateral_stiffness_N_per_m * offset.squaredNorm();
    const double along = tele.world().report().axis.dot(plant.data().tip.translation() - tip_v.translation());
    e += 0.5 * tele.blend().axial * tele.output().axial_stiffness_N_per_m * along * along;
  } else {
    e += potential_energy(sc.master, plant.data());
  }
  return e;
}

}  // namespace needle::haptics
