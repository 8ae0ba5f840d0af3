// needle-sim bench tick: the cost of one full servo tick (master model update, controller,
// multipliers, virtual robot integration) in nonholonomic contact. That the same ticks allocate
// nothing is a test (tests/haptics/test_bench_tick_allocations.cpp), not a column: counting would
// replace the C allocator of the program every trainee runs.
#include <chrono>
#include <cstdio>

#include "arg_list.hpp"
#include "asset_path.hpp"
#include "bench_table.hpp"
#include "command.hpp"
#include "haptics/sim/tick_workload.hpp"
#include "sample_stats.hpp"

namespace needle::cli {
namespace {

int run_bench_tick(ArgList& args) {
  const std::string scenario_path =
      args.value("--scenario").value_or((asset_dir() / "scenarios" / "nonholonomic_needle.json").string());
  const auto ticks_text = args.value("--ticks");
  const auto settle_text = args.value("--settle");
  const auto json = output_file(args, "--json");
  args.finish();
  const long ticks = ticks_text ? static_cast<long>(parse_whole(*ticks_text, "--ticks", 1, 100000000)) : 1000000;
  const double settle = settle_text ? parse_number(*settle_text, "--settle") : 8.0;
  if (!(settle > 0.0)) throw UsageError("--settle must be positive");

  BenchTable table({"virtual_substeps", "ticks", "median_us", "p99_us", "max_us"});
  haptics::Scenario scenario = haptics::load_scenario(scenario_path);
  for (int substeps : {1, 2, 4}) {
    scenario.virtual_substeps = substeps;
    haptics::TickWorkload workload(scenario, settle);
    std::vector<double> us(static_cast<size_t>(ticks));
    for (long k = 0; k < ticks; ++k) {
      const auto t0 = std::chrono::steady_clock::now();
      workload.tick();
      const auto t1 = std::chrono::steady_clock::now();
      us[static_cast<size_t>(k)] = std::chrono::duration<double, std::micro>(t1 - t0).count();
    }
    double worst = 0;
    for (double u : us) worst = std::max(worst, u);
    table.add_row({substeps, ticks, percentile(us, 0.5), percentile(us, 0.99), worst});
  }
  table.emit("servo tick in nonholonomic contact (" + scenario.name + " at t = " + std::to_string(settle) + " s, T = " + std::to_string(scenario.period_s * 1e3) + " ms)", json);
  return 0;
}

const CommandRegistrar reg{{"bench tick",
                            "needle-sim bench tick [--scenario FILE] [--settle S] [--ticks N] [--json FILE]\n"
                            "  --scenario FILE  a scenario reaching the tissue by t = S (default assets/scenarios/nonholonomic_needle.json)\n"
                            "  --settle S       the scenario is played S seconds, then its last tick is timed (default 8)\n"
                            "  --ticks N        ticks timed per configuration (default 1000000)\n"
                            "  --json FILE      also write the rows as JSON (median_us, p99_us, max_us, ...)\n"
                            "  rows: 1, 2 and 4 virtual sub-steps per tick (the scenarios use 1)",
                            run_bench_tick}};

}  // namespace
}  // namespace needle::cli
