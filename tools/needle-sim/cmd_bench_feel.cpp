// needle-sim bench feel: what the hand feels (issue 13), per scenario, law and phase of contact:
// the force held at rest in free motion, the sensed force's content in the 3-50 Hz band and above
// it, the needle's lateral speed in tissue and the position tracking. haptics/sim/feel_metrics.hpp
// measures; this file runs the scenarios and prints.
#include <chrono>
#include <cmath>
#include <cstdio>

#include "arg_list.hpp"
#include "asset_path.hpp"
#include "bench_table.hpp"
#include "command.hpp"
#include "haptics/sim/feel_metrics.hpp"

namespace needle::cli {
namespace {

nlohmann::json number_or_null(double v) { return std::isnan(v) ? nlohmann::json(nullptr) : nlohmann::json(v); }

std::vector<haptics::ControlLaw> laws_named(const std::string& text) {
  if (text == "both") return {haptics::ControlLaw::Thesis, haptics::ControlLaw::Tool};
  if (const auto law = haptics::control_law_named(text)) return {*law};
  throw UsageError("--law: expected thesis, tool or both, got '" + text + "'");
}

int run_bench_feel(ArgList& args) {
  const auto scenario_arg = args.value("--scenario");
  const std::vector<haptics::ControlLaw> laws = laws_named(args.value("--law").value_or("both"));
  const std::vector<bool> passivity = parse_on_off_both(args.value("--passivity").value_or("on"), "--passivity");
  const auto json = args.value("--json");
  args.finish();
  check_output_folder(json, "--json");
  std::vector<std::string> paths;
  if (scenario_arg) {
    paths.push_back(*scenario_arg);
  } else {
    for (const char* name : {"holonomic_sphere", "nonholonomic_needle", "tissue_block_layers", "lumbar_epidural", "liver_biopsy"})
      paths.push_back((asset_dir() / "scenarios" / (std::string(name) + ".json")).string());
  }

  BenchTable table({"scenario", "law", "passivity", "phase", "seconds", "free_force_rest_N", "force_band_rms_N", "force_hf_rms_N",
                    "max_lateral_speed_mps", "tracking_rms_m", "run_s", "faults", "hand_work_min_J", "world_dissipated_min_J",
                    "passivity_damped_s"});
  for (const std::string& path : paths) {
    const haptics::Scenario scenario = haptics::load_scenario(path);
    for (haptics::ControlLaw law : laws) {
      // The damper acts under the tool law only: the thesis's law runs once.
      const bool tool = law == haptics::ControlLaw::Tool;
      for (bool damper : tool ? passivity : std::vector<bool>{false}) {
        haptics::Scenario s = scenario;
        s.gains.law = law;
        if (!damper) s.gains.passivity.max_damping_per_tick = 0.0;
        const double rest = haptics::free_force_at_rest(s);
        const auto t0 = std::chrono::steady_clock::now();
        const haptics::SimResult run = haptics::run_closed_loop(s, true);
        const double run_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        const std::string faults = run.summary.faults.empty() ? "none" : run.summary.faults.front();
        for (const haptics::PhaseFeel& p : haptics::feel_by_phase(run.ticks, s.period_s)) {
          const bool free = p.phase == haptics::FeelPhase::Free;
          table.add_row({s.name, haptics::control_law_name(law), tool ? (damper ? "on" : "off") : "-",
                         haptics::feel_phase_name(p.phase), p.seconds, free ? nlohmann::json(rest) : nlohmann::json(nullptr),
                         p.force_band_rms_N, p.force_hf_rms_N, number_or_null(p.max_lateral_speed_mps), p.tracking_rms_m,
                         run_s, faults, run.summary.hand_work_min_J, run.summary.world_dissipated_min_J,
                         run.summary.passivity_damped_s});
        }
      }
    }
  }
  table.emit("what the hand feels: |F_h| band 3-50 Hz and above 50 Hz (zero-phase Butterworth), tissue from 0.3 s after "
             "entry, lateral speed from 1 s after entry; free_force_rest_N: mean |F_h| held still at the first waypoint",
             json);
  return 0;
}

const CommandRegistrar reg{{"bench feel",
                            "needle-sim bench feel [--scenario FILE] [--law thesis|tool|both] [--passivity on|off|both]\n"
                            "                      [--json FILE]\n"
                            "  --scenario FILE  one scenario (default: the two thesis scenarios and the layered ones)\n"
                            "  --law L          the controller: thesis (as the thesis prints it, corrected), tool, or both\n"
                            "                   side by side (default both)\n"
                            "  --passivity P    the passivity damper under the tool law: on (default), off, or both in turn\n"
                            "                   (what it costs in transparency, docs/CONTROLLER.md \"Passivity guaranteed\")\n"
                            "  --json FILE      also write the rows as JSON (its folder must exist)\n"
                            "  per scenario, law and phase (free, rigid contact, tissue): free_force_rest_N,\n"
                            "  force_band_rms_N (3-50 Hz), force_hf_rms_N (> 50 Hz), max_lateral_speed_mps, tracking_rms_m,\n"
                            "  run_s (wall time of the closed-loop run); per run: hand_work_min_J (least work of the hand on the\n"
                            "  stylus), world_dissipated_min_J (least of that work minus the change of the energy the world\n"
                            "  stores: < 0 means the world gave the hand energy it had not stored, docs/CONTROLLER.md),\n"
                            "  passivity_damped_s (time the passivity damper acted)",
                            run_bench_feel}};

}  // namespace
}  // namespace needle::cli
