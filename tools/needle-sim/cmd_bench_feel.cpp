// needle-sim bench feel: what the hand feels, per scenario, law and phase of contact:
// the force held at rest in free motion, the sensed force's content in the 3-50 Hz band and above
// it, the needle's lateral speed in tissue and the position tracking. haptics/sim/feel_metrics.hpp
// measures; this file runs the scenarios and prints.
#include <chrono>
#include <cmath>
#include <cstdio>

#include "asset_path.hpp"
#include "bench_table.hpp"
#include "command.hpp"
#include "flag_ranges.hpp"
#include "haptics/sim/feel_metrics.hpp"

namespace needle::cli {
namespace {

nlohmann::json number_or_null(double v) { return std::isnan(v) ? nlohmann::json(nullptr) : nlohmann::json(v); }

struct FeelFlags {
  std::optional<std::string> scenario, json;
  std::string law = "both";
  std::string passivity = "on";
};

int run(const FeelFlags& f) {
  const std::vector<haptics::ControlLaw> laws =
      f.law == "both" ? std::vector{haptics::ControlLaw::Thesis, haptics::ControlLaw::Tool}
                      : std::vector{*haptics::control_law_named(f.law)};
  std::vector<std::string> paths;
  if (f.scenario) {
    paths.push_back(*f.scenario);
  } else {
    for (const char* name :
         {"holonomic_sphere", "nonholonomic_needle", "tissue_block_layers", "lumbar_epidural", "liver_biopsy"})
      paths.push_back((asset_dir() / "scenarios" / (std::string(name) + ".json")).string());
  }

  BenchTable table({"scenario", "law", "passivity", "phase", "seconds", "free_force_rest_N", "force_band_rms_N",
                    "force_hf_rms_N", "max_lateral_speed_mps", "tracking_rms_m", "run_s", "faults", "hand_work_min_J",
                    "world_dissipated_min_J", "passivity_damped_s"});
  for (const std::string& path : paths) {
    const haptics::Scenario scenario = haptics::load_scenario(path);
    for (haptics::ControlLaw law : laws) {
      // The passivity controller acts under the tool law only: the thesis's law runs once.
      const bool tool = law == haptics::ControlLaw::Tool;
      for (bool on : tool ? passivity_settings(f.passivity) : std::vector<bool>{false}) {
        haptics::Scenario s = scenario;
        s.gains.law = law;
        if (!on) s.gains.passivity.max_damping_per_tick = 0.0;
        const double rest = haptics::free_force_at_rest(s);
        const auto t0 = std::chrono::steady_clock::now();
        const haptics::SimResult run = haptics::run_closed_loop(s, true);
        const double run_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        const std::string faults = run.summary.faults.empty() ? "none" : run.summary.faults.front();
        for (const haptics::PhaseFeel& p : haptics::feel_by_phase(run.ticks, s.period_s)) {
          const bool free = p.phase == haptics::FeelPhase::Free;
          table.add_row({s.name, haptics::control_law_name(law), tool ? (on ? "on" : "off") : "-",
                         haptics::feel_phase_name(p.phase), p.seconds,
                         free ? nlohmann::json(rest) : nlohmann::json(nullptr), p.force_band_rms_N, p.force_hf_rms_N,
                         number_or_null(p.max_lateral_speed_mps), p.tracking_rms_m, run_s, faults,
                         run.summary.hand_work_min_J, run.summary.world_dissipated_min_J,
                         run.summary.passivity_damped_s});
        }
      }
    }
  }
  table.emit(
      "what the hand feels: |F_h| band 3-50 Hz and above 50 Hz (zero-phase Butterworth), tissue from 0.3 s after "
      "entry, lateral speed from 1 s after entry; free_force_rest_N: mean |F_h| held still at the first waypoint",
      f.json);
  return 0;
}

// The options of bench feel, declared; what runs it once they are parsed.
Runner declare(CLI::App& app) {
  auto f = std::make_shared<FeelFlags>();
  add_text(app, "--scenario", f->scenario, "FILE",
           "one scenario (default: the two thesis scenarios and the layered ones)");
  add_choice(app, "--law", f->law,
             {haptics::control_law_name(haptics::ControlLaw::Thesis),
              haptics::control_law_name(haptics::ControlLaw::Tool), "both"},
             "the controller: thesis (as the thesis prints it, corrected), tool, or both side by side");
  add_passivity(app, f->passivity);
  add_output_file(app, "--json", f->json, "FILE", "also write the rows as JSON");
  app.footer(
      "per scenario, law and phase (free, rigid contact, tissue): free_force_rest_N, force_band_rms_N (3-50 Hz),\n"
      "force_hf_rms_N (> 50 Hz), max_lateral_speed_mps, tracking_rms_m, run_s (wall time of the closed-loop "
      "run);\n"
      "per run: hand_work_min_J (least work of the hand on the stylus), world_dissipated_min_J (least of that "
      "work\n"
      "minus the change of the energy the world stores: < 0 means the world gave the hand energy it had not\n"
      "stored, docs/CONTROLLER.md), passivity_damped_s (time the passivity controller acted)");
  return [f] { return run(*f); };
}

const CommandRegistrar reg{
    {"bench feel", "what the hand feels, per scenario, controller and phase of contact", declare}};

}  // namespace
}  // namespace needle::cli
