// needle-sim simulate: a scenario in closed loop without a device; per-tick CSV and summary.json.
#include <cstdio>
#include <filesystem>

#include "command.hpp"
#include "haptics/sim/sim_output.hpp"
#include "io/file_write.hpp"

namespace needle::cli {
namespace {

struct SimulateFlags {
  std::optional<std::string> scenario, out;
};

int run(const SimulateFlags& f) {
  const haptics::Scenario scenario = haptics::load_scenario(*f.scenario);
  io::make_folder(*f.out);
  const haptics::SimResult result = haptics::run_closed_loop(scenario, true);
  const std::string csv = (std::filesystem::path(*f.out) / "ticks.csv").string();
  const std::string summary = (std::filesystem::path(*f.out) / "summary.json").string();
  haptics::write_ticks_csv(csv, result.ticks, scenario.master.dof(), scenario.scene.tissue);
  haptics::write_summary_json(summary, result.summary);
  std::printf("%s: %.3f s simulated, %zu ticks -> %s, %s\n", scenario.name.c_str(), result.simulated_s,
              result.ticks.size(), csv.c_str(), summary.c_str());
  for (const std::string& fault : result.summary.faults) std::fprintf(stderr, "fault: %s\n", fault.c_str());
  return 0;
}

// The options of simulate, declared; what runs it once they are parsed.
Runner declare(CLI::App& app) {
  auto f = std::make_shared<SimulateFlags>();
  add_text(app, "--scenario", f->scenario, "FILE", "closed-loop scenario (assets/scenarios/*.json)")->required();
  add_text(app, "--out", f->out, "DIR", "writes DIR/ticks.csv (one row per servo tick) and DIR/summary.json")
      ->required();
  app.footer("faults, if any, are listed in summary.json and on stderr; the exit code stays 0");
  return [f] { return run(*f); };
}

const CommandRegistrar reg{
    {"simulate", "a scenario in closed loop without a device: per-tick CSV and summary.json", declare}};

}  // namespace
}  // namespace needle::cli
