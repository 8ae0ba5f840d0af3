#include "haptics/sim/closed_loop.hpp"

#include <cmath>

#include "haptics/sim/hand_port.hpp"

namespace needle::haptics {
namespace {

// Running RMS and max of a nonnegative error.
struct ErrorStats {
  double sum_sq = 0, max = 0;
  long count = 0;
  void add(double e) {
    sum_sq += e * e;
    max = std::max(max, e);
    ++count;
  }
  double rms() const { return count ? std::sqrt(sum_sq / count) : 0.0; }
};

bool finite(const VecN& v) { return v.allFinite(); }

}  // namespace

nlohmann::json SimSummary::to_json() const {
  nlohmann::json pops = nlohmann::json::array();
  for (const SimPuncture& p : punctures)
    pops.push_back({{"layer", p.layer}, {"depth_m", p.depth_m}, {"peak_force_N", p.peak_force_N}});
  return {{"position_rms_free_m", position_rms_free_m},
          {"position_max_free_m", position_max_free_m},
          {"position_rms_contact_m", position_rms_contact_m},
          {"position_max_contact_m", position_max_contact_m},
          {"force_rms_N", force_rms_N},
          {"force_max_N", force_max_N},
          {"max_penetration_m", max_penetration_m},
          {"max_lateral_speed_mps", max_lateral_speed_mps},
          {"max_axis_deviation_m", max_axis_deviation_m},
          {"energy_error_J", energy_error_J},
          {"punctures", pops},
          {"tissue_work_J", tissue_work_J},
          {"hand_work_J", hand_work_J},
          {"hand_work_min_J", hand_work_min_J},
          {"world_dissipated_min_J", world_dissipated_min_J},
          {"saturated_s", saturated_s},
          {"passivity_damped_s", passivity_damped_s},
          {"faults", faults}};
}

SimResult run_closed_loop(const Scenario& sc, bool keep_ticks, const std::function<void(const TickRecord&)>& on_tick) {
  const int n = sc.master.dof();
  const double T = sc.period_s;
  Teleoperation tele(sc.master, sc.virt, sc.scene, sc.gains, T, sc.virtual_substeps, sc.device);
  MasterPlant plant(sc.master, sc.device, sc.hand, sc.master_integrator, sc.master_substeps);
  ForceSensor sensor(sc.sensor);
  tele.reset(sc.q0, VecN::Zero(n));
  plant.reset(sc.q0, VecN::Zero(n));
  sensor.reset(Wrench::Zero());
  const double e0 = plant.energy() + tele.world().energy();
  const double stored0 = world_stored_energy(sc, plant, tele);

  SimResult result;
  ErrorStats free_pos, contact_pos, force;
  double deviation = 0.0;
  const long ticks = std::lround(sc.duration_s / T);
  if (keep_ticks) result.ticks.reserve(static_cast<size_t>(ticks));
  TickInput in;
  TickRecord rec;
  for (long k = 0; k < ticks; ++k) {
    const double t = k * T;
    in.q_m = plant.q();
    in.dq_m = plant.dq();
    in.wrench_h = sensor.read(plant.hand_wrench(), T);
    const TickOutput& out = tele.step(in);
    plant.advance(out.tau_m, sc.trajectory, t, T);

    const VirtualWorld& world = tele.world();
    const ContactReport& c = world.report();
    rec.t = t + T;
    rec.q_m = plant.q();
    rec.q_v = world.q();
    rec.x_m = plant.data().tip.translation() + sc.base_in_world;
    rec.x_v = world.data().tip.translation() + sc.base_in_world;
    rec.needle_v = world.data().tip.linear().col(0);
    rec.tau_m = out.tau_m;
    rec.force_h = in.wrench_h.head<3>();
    rec.force_v = c.force_rigid;
    rec.lambda_v[0] = c.mode == ContactMode::Holonomic ? c.lambda_rigid : c.lambda_tissue[0];
    rec.lambda_v[1] = c.mode == ContactMode::Holonomic ? 0.0 : c.lambda_tissue[1];
    rec.lambda_m[0] = out.lambda_m[0];
    rec.lambda_m[1] = out.lambda_m[1];
    rec.phi = c.phi;
    rec.psi[0] = c.psi[0];
    rec.psi[1] = c.psi[1];
    rec.energy = plant.energy() + world.energy();
    rec.mode = c.mode;
    rec.axial_force_N = world.tissue().out.axial_force_N;
    rec.layer = world.tissue().out.holding_layer;
    rec.hand_work_J = plant.hand_port_work();
    rec.world_stored_J = world_stored_energy(sc, plant, tele) - stored0;
    rec.saturated = out.saturated || plant.saturated();
    rec.passivity_damping_per_s = out.passivity_damping_per_s;
    rec.passivity_acted = out.passivity_acted();
    rec.position_error = (rec.x_m - rec.x_v).norm();
    rec.force_error = 0.0;

    // A state that is not finite is a latched fault, found before the tick enters the summary or
    // the ticks: summary.json never holds a NaN.
    if (!finite(plant.q()) || !finite(plant.dq()) || !finite(world.q()) || !finite(world.dq()) ||
        !std::isfinite(rec.energy) || !finite(rec.tau_m) || !std::isfinite(rec.hand_work_J) ||
        !std::isfinite(rec.world_stored_J) || !rec.force_h.allFinite()) {
      result.summary.faults.push_back("non_finite_state at t=" + std::to_string(rec.t) + " s");
      break;
    }

    // Metrics: free vs contact by the virtual tool's contact mode.
    if (c.mode == ContactMode::Free) {
      free_pos.add(rec.position_error);
    } else {
      contact_pos.add(rec.position_error);
      rec.force_error = c.mode == ContactMode::Holonomic
                            ? (out.force_h_normal - c.force_rigid).norm()
                            : std::hypot(out.lambda_m[0] + c.lambda_tissue[0], out.lambda_m[1] + c.lambda_tissue[1]);
      force.add(rec.force_error);
    }
    SimSummary& s = result.summary;
    if (c.mode == ContactMode::Holonomic) s.max_penetration_m = std::max(s.max_penetration_m, -c.phi);
    if (c.mode == ContactMode::Nonholonomic) {
      const double lateral = std::hypot(c.psi[0], c.psi[1]);
      s.max_lateral_speed_mps = std::max(s.max_lateral_speed_mps, lateral);
      deviation += lateral * T;
      s.max_axis_deviation_m = std::max(s.max_axis_deviation_m, deviation);
    } else {
      deviation = 0.0;
    }
    const TissueOutput& tissue = world.tissue().out;
    if (tissue.punctured_layer >= 0)
      s.punctures.push_back(
          {sc.scene.tissue.layer(tissue.punctured_layer).name, world.tissue().s, tissue.axial_force_N, rec.t});
    s.tissue_work_J = world.tissue().tissue_work_J;
    s.hand_work_J = rec.hand_work_J;
    s.hand_work_min_J = std::min(s.hand_work_min_J, rec.hand_work_J);
    s.world_dissipated_min_J = std::min(s.world_dissipated_min_J, rec.hand_work_J - rec.world_stored_J);
    s.saturated_s += rec.saturated ? T : 0.0;
    s.passivity_damped_s += rec.passivity_acted ? T : 0.0;
    s.energy_error_J =
        std::max(s.energy_error_J, std::abs(rec.energy - e0 - plant.external_work() - world.external_work()));
    if (keep_ticks) result.ticks.push_back(rec);
    if (on_tick) on_tick(rec);
    result.simulated_s = rec.t;

    // Latched faults end the run, naming the cause.
    if (std::abs(rec.energy) > sc.energy_bound_J) {
      s.faults.push_back("energy_bound_exceeded at t=" + std::to_string(rec.t) + " s: |E| = " +
                         std::to_string(std::abs(rec.energy)) + " J > " + std::to_string(sc.energy_bound_J) + " J");
    } else if (rec.position_error > sc.divergence_bound_m) {
      s.faults.push_back("tracking_diverged at t=" + std::to_string(rec.t) +
                         " s: |x_m - x_v| = " + std::to_string(rec.position_error) + " m");
    }
    if (!s.faults.empty()) break;
  }
  SimSummary& s = result.summary;
  s.position_rms_free_m = free_pos.rms();
  s.position_max_free_m = free_pos.max;
  s.position_rms_contact_m = contact_pos.rms();
  s.position_max_contact_m = contact_pos.max;
  s.force_rms_N = force.rms();
  s.force_max_N = force.max;
  return result;
}

}  // namespace needle::haptics
