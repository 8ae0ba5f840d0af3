#include "haptics/sim/tick_workload.hpp"

#include <stdexcept>

#include "haptics/sim/master_plant.hpp"

namespace needle::haptics {

TickWorkload::TickWorkload(const Scenario& sc, double settle_s) {
  const int n = sc.master.dof();
  tele_ = std::make_unique<Teleoperation>(sc.master, sc.virt, sc.scene, sc.gains, sc.period_s, sc.virtual_substeps);
  MasterPlant plant(sc.master, sc.device, sc.hand, sc.master_integrator, sc.master_substeps);
  ForceSensor sensor(sc.sensor);
  tele_->reset(sc.q0, VecN::Zero(n));
  plant.reset(sc.q0, VecN::Zero(n));
  const long ticks = std::lround(settle_s / sc.period_s);
  for (long k = 0; k < ticks; ++k) {
    input_ = {plant.q(), plant.dq(), sensor.read(plant.hand_wrench(), sc.period_s)};
    plant.advance(tele_->step(input_).tau_m, sc.trajectory, k * sc.period_s, sc.period_s);
  }
  if (tele_->world().report().mode != ContactMode::Nonholonomic)
    throw std::runtime_error(sc.source + ": the needle is not in the tissue after " + std::to_string(settle_s) + " s");
  input_ = {plant.q(), plant.dq(), sensor.read(plant.hand_wrench(), sc.period_s)};
}

}  // namespace needle::haptics
