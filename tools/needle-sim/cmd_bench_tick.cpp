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
#include "haptics/sim/tick_workload.hpp"
#include "sample_stats.hpp"

namespace needle::cli {
namespace {

struct TickFlags {
  std::optional<std::string> scenario, json;
  double settle_s = 8.0;
  long long ticks = 1000000;
};

// The patient's row: assets/scenarios/epidural_patient.json played this long puts the tip in the
// interspinous ligament, the shaft through the skin, the fat and the supraspinous ligament.
constexpr double kPatientSettle_s = 24.0;

// (workload, ticks, substeps) => the table's row of their times.
void time_ticks(BenchTable& table, const std::string& name, haptics::TickWorkload& workload, int substeps, long ticks) {
  std::vector<double> us(static_cast<size_t>(ticks));
  for (long k = 0; k < ticks; ++k) {
    const auto t0 = std::chrono::steady_clock::now();
    workload.tick();
    const auto t1 = std::chrono::steady_clock::now();
    us[static_cast<size_t>(k)] = std::chrono::duration<double, std::micro>(t1 - t0).count();
  }
  double worst = 0;
  for (double u : us) worst = std::max(worst, u);
  table.add_row({name, substeps, ticks, percentile(us, 0.5), percentile(us, 0.99), worst});
}

int run(const TickFlags& f) {
  const std::string scenario_path =
      f.scenario.value_or((asset_dir() / "scenarios" / "nonholonomic_needle.json").string());
  const long ticks = long(f.ticks);
  const double settle = f.settle_s;

  BenchTable table({"scenario", "virtual_substeps", "ticks", "median_us", "p99_us", "max_us"});
  haptics::Scenario scenario = haptics::load_scenario(scenario_path);
  for (int substeps : {1, 2, 4}) {
    scenario.virtual_substeps = substeps;
    haptics::TickWorkload workload(scenario, settle);
    time_ticks(table, scenario.name, workload, substeps, ticks);
  }
  const haptics::Scenario patient = haptics::load_scenario((asset_dir() / "scenarios" / "epidural_patient.json").string());
  haptics::TickWorkload on_patient(patient, kPatientSettle_s);
  time_ticks(table, patient.name, on_patient, patient.virtual_substeps, ticks);
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
  add_output_file(app, "--json", f->json, "FILE", "also write the rows as JSON (median_us, p99_us, max_us, ...)");
  app.footer("rows: 1, 2 and 4 virtual sub-steps per tick (the scenarios use 1), then the generated patient's "
             "(assets/scenarios/epidural_patient.json at 24 s: the shaft through skin, fat, supraspinous and interspinous ligament)");
  return [f] { return run(*f); };
}

const CommandRegistrar reg{{"bench tick", "the cost of one full servo tick in nonholonomic contact and on the patient", declare}};

}  // namespace
}  // namespace needle::cli
