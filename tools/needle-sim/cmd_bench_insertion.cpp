// needle-sim bench insertion: the tissue model's own force-depth curve. The tip is driven at
// constant speed along a line through a scenario's tissue, held and withdrawn (no robots, no
// controller); haptics/tissue/kinematic_insertion.hpp does the run, this file parses and prints.
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "arg_list.hpp"
#include "bench_table.hpp"
#include "command.hpp"
#include "haptics/sim/scenario.hpp"
#include "haptics/tissue/kinematic_insertion.hpp"
#include "io/write_file.hpp"
#include "ui/line_chart.hpp"

namespace needle::cli {
namespace {

Eigen::Vector3d parse_vec3(const std::string& text, const std::string& flag) {
  const std::vector<double> v = parse_number_list(text, flag);
  if (v.size() != 3) throw UsageError(flag + ": expected three numbers X,Y,Z, got '" + text + "'");
  return {v[0], v[1], v[2]};
}

double parse_positive(const std::string& text, const std::string& flag) {
  const double v = parse_number(text, flag);
  if (!(v > 0.0)) throw UsageError(flag + ": must be > 0, got '" + text + "'");
  return v;
}

// An output file's folder must exist before the run, not be found missing after it.
void check_output_folder(const std::optional<std::string>& file, const std::string& flag) {
  if (!file) return;
  const std::filesystem::path folder = std::filesystem::absolute(*file).parent_path();
  if (!std::filesystem::is_directory(folder))
    throw UsageError(flag + ": folder " + folder.string() + " does not exist");
}

std::string layer_name(const haptics::TissueModel& model, int layer) {
  return layer < 0 ? "" : model.layer(layer).name;
}

nlohmann::json run_json(const haptics::TissueModel& model, const haptics::InsertionRun& run,
                        const std::vector<haptics::LayerBoundary>& boundaries) {
  nlohmann::json samples = nlohmann::json::array(), punctures = nlohmann::json::array(), rest = nlohmann::json::array();
  for (const auto& s : run.samples)
    samples.push_back({{"t", s.t},
                       {"depth_m", s.depth_m},
                       {"axial_force_N", s.axial_force_N},
                       {"layer", layer_name(model, s.layer)}});
  for (const auto& p : run.punctures)
    punctures.push_back(
        {{"layer", layer_name(model, p.layer)}, {"depth_m", p.depth_m}, {"peak_force_N", p.peak_force_N}});
  for (const auto& b : boundaries) rest.push_back({{"depth_m", b.depth_m}, {"layer", layer_name(model, b.layer)}});
  nlohmann::json stop = nullptr;
  if (run.hard_stop) stop = {{"layer", layer_name(model, run.hard_stop->layer)}, {"depth_m", run.hard_stop->depth_m}};
  return {{"samples", samples},
          {"punctures", punctures},
          {"tissue_work_J", run.tissue_work_J},
          {"tick_us_median", run.tick_us_median},
          {"hard_stop", stop},
          {"boundaries", rest}};
}

void write_plot(const std::string& file, const std::string& title, const haptics::TissueModel& model,
                const haptics::InsertionRun& run, const std::vector<haptics::LayerBoundary>& boundaries) {
  ui::LineChart chart{title, "depth (mm)", "axial force (N)", {}, {}};
  ui::ChartLine in{"insertion", {}, {}, {30, 90, 200}}, out{"hold and withdrawal", {}, {}, {220, 90, 40}};
  // The insertion ends where the tip first reaches its deepest point; the hold is a vertical segment there.
  const auto deepest = std::max_element(run.samples.begin(), run.samples.end(),
                                        [](const auto& a, const auto& b) { return a.depth_m < b.depth_m; });
  for (auto it = run.samples.begin(); it != run.samples.end(); ++it)
    for (ui::ChartLine* line : {&in, &out})
      if ((line == &in) == (it <= deepest) || it == deepest) {
        line->x.push_back(1e3 * it->depth_m);
        line->y.push_back(it->axial_force_N);
      }
  chart.lines = {in, out};
  for (const auto& b : boundaries)
    chart.markers.push_back({1e3 * b.depth_m, b.layer < 0 ? "(no layer)" : model.layer(b.layer).name});
  engine::write_png(file, ui::draw_line_chart(chart, 1200, 700));
}

int run_bench_insertion(ArgList& args) {
  const std::string scenario_path = args.required("--scenario");
  const Eigen::Vector3d from_world = parse_vec3(args.required("--from"), "--from");
  const Eigen::Vector3d dir = parse_vec3(args.required("--dir"), "--dir");
  const double depth = parse_positive(args.required("--depth"), "--depth");
  const double speed = parse_positive(args.required("--speed"), "--speed");
  const double hold = parse_number(args.value("--hold").value_or("0"), "--hold");
  const auto json_path = args.value("--json");
  const auto plot_path = args.value("--plot");
  args.finish();
  if (hold < 0.0) throw UsageError("--hold: must be >= 0");
  if (dir.norm() < 1e-12) throw UsageError("--dir: must not be the zero vector");
  check_output_folder(json_path, "--json");
  check_output_folder(plot_path, "--plot");

  const haptics::Scenario scenario = haptics::load_scenario(scenario_path);
  if (scenario.tissue.empty()) throw UsageError("--scenario: " + scenario_path + " has no tissue");
  haptics::InsertionPlan plan;
  plan.from = from_world - scenario.base_in_world;  // the scenario's tissue is in the robots' base frame
  plan.dir = dir.normalized();
  plan.depth_m = depth;
  plan.speed_mps = speed;
  plan.hold_s = hold;
  plan.period_s = scenario.period_s;
  const haptics::InsertionRun run = haptics::run_kinematic_insertion(scenario.tissue, plan);
  // The layers along the line as far as the tip went (and the rigid surface that stopped it).
  const double reached = run.hard_stop ? std::min(depth, run.hard_stop->depth_m + 1e-3) : depth;
  const auto boundaries = haptics::layer_boundaries(scenario.tissue, plan.from, plan.dir, reached);

  BenchTable table({"layer", "depth_m", "peak_force_N"});
  for (const auto& p : run.punctures) table.add_row({layer_name(scenario.tissue, p.layer), p.depth_m, p.peak_force_N});
  table.print("bench insertion: " + scenario.name + ", punctures (" + std::to_string(run.samples.size()) +
              " ticks of " + std::to_string(scenario.period_s * 1e3) + " ms)");
  if (run.hard_stop)
    std::printf("hard stop: %s at depth %.4g m (a rigid layer: the drive stops there)\n",
                layer_name(scenario.tissue, run.hard_stop->layer).c_str(), run.hard_stop->depth_m);
  std::printf("tissue_work_J %.6g, tick_us_median %.4g\n", run.tissue_work_J, run.tick_us_median);
  if (json_path) {
    io::write_file(*json_path, run_json(scenario.tissue, run, boundaries).dump(1) + "\n");
  }
  if (plot_path) {
    char title[160];
    std::snprintf(title, sizeof title, "%s: %.3g mm/s in, %.3g s held, out", scenario.name.c_str(), speed * 1e3, hold);
    write_plot(*plot_path, title, scenario.tissue, run, boundaries);
  }
  return 0;
}

const CommandRegistrar reg{
    {"bench insertion",
     "needle-sim bench insertion --scenario FILE --from X,Y,Z --dir DX,DY,DZ --depth M --speed MPS [--hold S] [--json "
     "OUT] [--plot OUT.png]\n"
     "  --scenario FILE  a scenario with a tissue (assets/scenarios/*.json); only its tissue and period are used\n"
     "  --from X,Y,Z     the tip's start, world frame (m)\n"
     "  --dir DX,DY,DZ   insertion direction (normalized)\n"
     "  --depth M        how far along dir the tip is driven (m); a rigid layer on the way stops it\n"
     "  --speed MPS      constant speed in and out (m/s)\n"
     "  --hold S         seconds held at the deepest point (default 0)\n"
     "  --json OUT       samples {t, depth_m, axial_force_N, layer}, punctures {layer, depth_m, peak_force_N},\n"
     "                   tissue_work_J, tick_us_median, hard_stop, boundaries (the layers along the line at rest)\n"
     "  --plot OUT.png   force against depth with the layer boundaries",
     run_bench_insertion}};

}  // namespace
}  // namespace needle::cli
