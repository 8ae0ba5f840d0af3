// needle-sim bench tick: the cost of one full servo tick (master model update, controller,
// multipliers, virtual robot integration) in nonholonomic contact, and on the generated patient
// with the shaft through four of its layers. That the same ticks allocate
// nothing is a test (tests/haptics/test_bench_tick_allocations.cpp), not a column: counting would
// replace the C allocator of the program every trainee runs.
#include <chrono>
#include <cstdio>

#include "asset_path.hpp"
#include "bench_table.hpp"
#include "command.hpp"
#include "flag_ranges.hpp"
#include "haptics/realtime/syringe_servo_step.hpp"
#include "haptics/sim/tick_workload.hpp"
#include "sample_stats.hpp"

namespace needle::cli {
namespace {

struct TickFlags {
  std::optional<std::string> scenario, json;
  double settle_s = 8.0;
  long long ticks = 1000000;
  std::string syringe;  // "": none
};

// The loss-of-resistance syringe's share of a tick, as haptics::SyringeServoStep runs it after the
// needle's step: the tissue at the opening, the flow path, the syringe's step under an 11 N thumb
// (the loss-of-resistance syringe's press, docs/TISSUE.md) and its snapshot.
class SyringeTick {
 public:
  SyringeTick(const haptics::Scenario& scenario, haptics::SyringeFluid fluid, double dt)
      : tissue_(scenario.scene.tissue), dt_(dt) {
    params_ = scenario.syringe.value_or(haptics::SyringeParams{});
    params_.fluid = fluid;
    for (const haptics::TissueLayer& layer : tissue_.layers())
      if (!layer.mechanics.rigid && !layer.injection)
        throw UsageError("--syringe: " + scenario.source + ": layer \"" + layer.name +
                         "\" has no injection parameters");
    state_ = haptics::syringe_at_rest(params_);
  }
  void tick(const haptics::Teleoperation& tele) {
    const haptics::TissueState& track = tele.world().tissue();
    const int layer = track.on_track ? track.out.opening_layer : -1;
    const haptics::LayerInjection* tip = layer >= 0 ? &*tissue_.layer(layer).injection : nullptr;
    haptics::step_syringe(params_, state_, 11.0, haptics::flow_path(params_, tip), dt_);
    snapshot_ = haptics::syringe_snapshot(params_, state_, layer);
  }

 private:
  const haptics::TissueModel& tissue_;
  double dt_;
  haptics::SyringeParams params_;
  haptics::SyringeState state_;
  haptics::SyringeSnapshot snapshot_;
};

// The patient's row: assets/scenarios/epidural_patient.json played this long puts the tip in the
// interspinous ligament, the shaft through the skin, the fat and the supraspinous ligament.
constexpr double kPatientSettle_s = 24.0;

// (scenario, its workload, ticks, substeps, syringe) => the table's rows of their times: one, or with a
// syringe one without and one with it, blocks of 1000 ticks of each alternating so that both rows
// see the same machine.
void time_ticks(BenchTable& table, const haptics::Scenario& scenario, haptics::TickWorkload& workload, int substeps,
                long ticks, const std::optional<haptics::SyringeFluid>& fluid, const std::string& fluid_name) {
  std::optional<SyringeTick> syringe;
  if (fluid) syringe.emplace(scenario, *fluid, scenario.period_s);
  const int variants = fluid ? 2 : 1;
  std::vector<double> us[2];
  for (long k = 0; long(us[0].size()) < ticks || long(us[variants - 1].size()) < ticks; ++k) {
    const int variant = fluid ? int(k / 1000 % 2) : 0;
    if (long(us[variant].size()) == ticks) continue;
    const auto t0 = std::chrono::steady_clock::now();
    workload.tick();
    if (variant == 1) syringe->tick(workload.teleoperation());
    const auto t1 = std::chrono::steady_clock::now();
    us[variant].push_back(std::chrono::duration<double, std::micro>(t1 - t0).count());
  }
  for (int variant = 0; variant < variants; ++variant) {
    double worst = 0;
    for (double u : us[variant]) worst = std::max(worst, u);
    table.add_row({scenario.name, substeps, variant == 0 ? "none" : fluid_name, long(us[variant].size()),
                   percentile(us[variant], 0.5), percentile(us[variant], 0.99), worst});
  }
}

int run(const TickFlags& f) {
  const std::string scenario_path =
      f.scenario.value_or((asset_dir() / "scenarios" / "nonholonomic_needle.json").string());
  const long ticks = long(f.ticks);
  const double settle = f.settle_s;

  BenchTable table({"scenario", "virtual_substeps", "syringe", "ticks", "median_us", "p99_us", "max_us"});
  haptics::Scenario scenario = haptics::load_scenario(scenario_path);
  const std::optional<haptics::SyringeFluid> fluid = haptics::parse_syringe_fluid(f.syringe.c_str());
  for (int substeps : {1, 2, 4}) {
    scenario.virtual_substeps = substeps;
    haptics::TickWorkload workload(scenario, settle);
    time_ticks(table, scenario, workload, substeps, ticks, fluid, f.syringe);
  }
  const haptics::Scenario patient =
      haptics::load_scenario((asset_dir() / "scenarios" / "epidural_patient.json").string());
  haptics::TickWorkload on_patient(patient, kPatientSettle_s);
  time_ticks(table, patient, on_patient, patient.virtual_substeps, ticks, fluid, f.syringe);
  table.emit("servo tick in nonholonomic contact (" + scenario.name + " at t = " + std::to_string(settle) + " s, " +
                 patient.name + " at t = " + std::to_string(kPatientSettle_s) + " s: the shaft through skin, fat, " +
                 "supraspinous and interspinous ligament; T = " + std::to_string(scenario.period_s * 1e3) + " ms)",
             f.json);
  return 0;
}

// The options of bench tick, declared; what runs it once they are parsed.
Runner declare(CLI::App& app) {
  auto f = std::make_shared<TickFlags>();
  add_text(app, "--scenario", f->scenario, "FILE",
           "a scenario reaching the tissue by t = S (default assets/scenarios/nonholonomic_needle.json)");
  add_number(app, "--settle", f->settle_s, kSettle_s, "S",
             "the scenario is played S seconds, then its last tick is timed");
  add_whole(app, "--ticks", f->ticks, kTimedTicks, "N", "ticks timed per configuration");
  add_choice(app, "--syringe", f->syringe, {"saline", "air"},
             "also time the tick with a loss-of-resistance syringe of this fluid pressed with 11 N (the scenario's\n"
             "tissue must give its layers' injection keys; e.g. assets/scenarios/epidural.json with --settle 20)");
  add_output_file(app, "--json", f->json, "FILE",
                  "also write the rows as JSON (scenario, syringe, median_us, p99_us, max_us, ...)");
  app.footer(
      "rows: 1, 2 and 4 virtual sub-steps per tick (the scenarios use 1), then the generated patient's "
      "(assets/scenarios/epidural_patient.json at 24 s: the shaft through skin, fat, supraspinous and interspinous "
      "ligament); "
      "with --syringe each without and with it");
  return [f] { return run(*f); };
}

const CommandRegistrar reg{
    {"bench tick", "the cost of one full servo tick in nonholonomic contact and on the patient", declare}};

}  // namespace
}  // namespace needle::cli
