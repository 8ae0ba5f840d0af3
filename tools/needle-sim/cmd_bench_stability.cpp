// needle-sim bench stability: stress sweeps of the closed loop; each run ends bounded or in a
// latched fault that names its cause.
#include <chrono>
#include <cmath>
#include <cstdio>

#include "asset_path.hpp"
#include "bench_table.hpp"
#include "command.hpp"
#include "flag_ranges.hpp"
#include "haptics/sim/closed_loop.hpp"
#include "haptics/sim/stress_cases.hpp"

namespace needle::cli {
namespace {

struct StabilityFlags {
  std::optional<std::string> json;
  double sustained_s = 3600.0;
  std::string passivity = "on";
};

int run(const StabilityFlags& f) {
  const double sustained = f.sustained_s;
  const auto dir = asset_dir() / "scenarios";
  const haptics::Scenario h = haptics::load_scenario((dir / "holonomic_sphere.json").string());
  const haptics::Scenario nh = haptics::load_scenario((dir / "nonholonomic_needle.json").string());
  std::vector<haptics::StressCase> cases = haptics::stress_cases(h, nh, sustained);
  for (const char* name : {"tissue_block_layers", "lumbar_epidural", "liver_biopsy"}) {
    std::vector<haptics::StressCase> layered =
        haptics::layered_stress_cases(haptics::load_scenario((dir / (std::string(name) + ".json")).string()));
    cases.insert(cases.end(), std::make_move_iterator(layered.begin()), std::make_move_iterator(layered.end()));
  }

  BenchTable table({"sweep", "value", "passivity", "outcome", "simulated_s", "max_abs_energy_J", "energy_error_J",
                    "position_max_contact_m", "force_max_N", "max_penetration_m", "max_lateral_speed_mps", "wall_s",
                    "punctures", "tissue_work_J", "world_dissipated_min_J", "passivity_damped_s", "saturated_s"});
  for (const haptics::StressCase& c : cases)
    for (bool on : passivity_settings(f.passivity)) {
      haptics::Scenario scenario = c.scenario;
      if (!on) scenario.gains.passivity.max_damping_per_tick = 0.0;
      double max_energy = 0;
      const auto t0 = std::chrono::steady_clock::now();
      const haptics::SimResult r = haptics::run_closed_loop(scenario, false, [&](const haptics::TickRecord& t) {
        max_energy = std::max(max_energy, std::abs(t.energy));
      });
      const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      const haptics::SimSummary& s = r.summary;
      table.add_row({c.name, c.value, on ? "on" : "off", s.faults.empty() ? std::string("bounded") : s.faults.front(),
                     r.simulated_s, max_energy, s.energy_error_J, s.position_max_contact_m, s.force_max_N,
                     s.max_penetration_m, s.max_lateral_speed_mps, wall, s.punctures.size(), s.tissue_work_J,
                     s.world_dissipated_min_J, s.passivity_damped_s, s.saturated_s});
    }
  table.emit("closed-loop stress (energy bound " + std::to_string(h.energy_bound_J) + " J, divergence bound " +
                 std::to_string(h.divergence_bound_m) +
                 " m; K_crit = 2b/T = " + std::to_string(haptics::passivity_stiffness_bound(h)) + " N/m)",
             f.json);
  return 0;
}

// The options of bench stability, declared; what runs it once they are parsed.
Runner declare(CLI::App& app) {
  auto f = std::make_shared<StabilityFlags>();
  add_number(app, "--sustained", f->sustained_s, kSustained_s, "S",
             "simulated seconds of the sustained-contact run (3600 s: about two minutes of wall time)");
  add_passivity(app, f->passivity);
  add_output_file(app, "--json", f->json, "FILE", "also write the rows as JSON");
  app.footer(
      "sweeps: gains x0.1..x100, period x1..x8, singular poses, 2x force-limit push, sustained contact,\n"
      "penalty stiffness across K_crit = 2(b - |B|)/T; in the layered scenarios (tissue_block_layers,\n"
      "lumbar_epidural, liver_biopsy): puncture force, friction and stiffness x0.1..x10, period x1..x8,\n"
      "a push onto bone at 2x the force limit (where the tissue has bone)");
  return [f] { return run(*f); };
}

const CommandRegistrar reg{
    {"bench stability", "stress sweeps of the closed loop: each run bounded or a latched fault", declare}};

}  // namespace
}  // namespace needle::cli
