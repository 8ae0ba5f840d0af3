// A scenario run without a device: controller at the servo period, the master device and hand
// integrated at a finer step, the sensor between them. Records every tick and summarizes.
// A run ends at its duration or at the first latched fault (non-finite state, energy outside
// ±energy_bound_J, master/virtual tips farther apart than divergence_bound_m).
#pragma once

#include <functional>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "haptics/sim/scenario.hpp"

namespace needle::haptics {

struct TickRecord {
  double t = 0.0;
  VecN q_m, q_v;
  Eigen::Vector3d x_m, x_v;     // tips, world frame
  Eigen::Vector3d needle_v;     // virtual needle axis x₅
  Eigen::Vector3d force_h;      // sensed hand force on the stylus
  Eigen::Vector3d force_v;      // tool on rigid surface (3.16)
  double lambda_v[2] = {0, 0};  // rigid: λ (3.15) in [0]; tissue: (3.22)
  double lambda_m[2] = {0, 0};  // (3.24)
  double phi = 0.0;
  double psi[2] = {0, 0};
  double energy = 0.0;  // master + hand + virtual mechanical energy
  VecN tau_m;           // master command of the tick
  ContactMode mode = ContactMode::Free;
  double position_error = 0.0;  // |x_m − x_v|
  double force_error = 0.0;     // rigid: |F_h,n − F_v|; tissue: |λ_m + λ_v|
  double axial_force_N = 0.0;   // the tissue's along the needle (needle on tissue, > 0 resists advancing)
  int layer = -1;               // the tissue layer holding the tip, −1 in none
  // The hand's port (forces and torques through the sensor, haptics/sim/hand_port.hpp): the work
  // the hand has done on the stylus since the start, and the change of the energy the world holds
  // and may give back. Their difference is what the world dissipated (≥ 0 when it is passive).
  double hand_work_J = 0.0;
  double world_stored_J = 0.0;
  bool saturated = false;                // the device scaled the command down to its force limit
  double passivity_damping_per_s = 0.0;  // β of the passivity damper (tool law), 0 while off
  bool passivity_acted = false;          // the passivity controller withheld or damped
};

// A surface that gave way in closed loop (as bench insertion's InsertionPuncture, the depth being the
// tip's travel along the needle since it met the tissue).
struct SimPuncture {
  std::string layer;
  double depth_m = 0.0;
  double peak_force_N = 0.0;  // the tissue's axial force when it gave way
  double t = 0.0;
};

struct SimSummary {
  double position_rms_free_m = 0, position_max_free_m = 0;
  double position_rms_contact_m = 0, position_max_contact_m = 0;
  double force_rms_N = 0, force_max_N = 0;
  double max_penetration_m = 0;        // into the rigid surface
  double max_lateral_speed_mps = 0;    // |ψ| in tissue
  double max_axis_deviation_m = 0;     // ∫|ψ| dt over each stay in tissue
  double energy_error_J = 0;           // max |E(t) − E(0) − W_ext(t)|
  std::vector<SimPuncture> punctures;  // in order
  double tissue_work_J = 0;            // work of the needle on the tissue (≥ 0: the tissue is passive)
  double hand_work_J = 0;              // work of the hand on the stylus over the run (forces and torques)
  double hand_work_min_J = 0;          // its least value over the run (< 0: the world has pushed the hand)
  double world_dissipated_min_J = 0;   // least of hand work − Δ(world's stored energy) (≥ 0 when passive)
  double saturated_s = 0;              // time the device held the command at its force limit
  double passivity_damped_s = 0;       // time the passivity controller acted (withheld or damped)
  std::vector<std::string> faults;
  nlohmann::json to_json() const;  // the keys, SI units
};

struct SimResult {
  std::vector<TickRecord> ticks;  // empty unless asked for
  SimSummary summary;
  double simulated_s = 0.0;
};

// `on_tick` (optional) sees every record as it is made.
SimResult run_closed_loop(const Scenario& scenario, bool keep_ticks,
                          const std::function<void(const TickRecord&)>& on_tick = {});

}  // namespace needle::haptics
