// needle-sim bench insertion: the tissue model's own force-depth curve. The tip is driven at
// constant speed along a line through a scenario's tissue, held and withdrawn (no robots, no
// controller); haptics/tissue/kinematic_insertion.hpp does the run, this file parses and prints.
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "bench_table.hpp"
#include "command.hpp"
#include "flag_ranges.hpp"
#include "haptics/sim/scenario.hpp"
#include "haptics/syringe/syringe_insertion.hpp"
#include "haptics/tissue/kinematic_insertion.hpp"
#include "io/file_write.hpp"
#include "ui/line_chart.hpp"

namespace needle::cli {
namespace {

struct InsertionFlags {
  std::optional<std::string> scenario, json, plot;
  std::vector<double> from, dir;
  std::optional<double> depth, speed;
  double hold = 0.0;
  std::string syringe;  // "": none
  std::optional<double> plunger_force;
};

std::string layer_name(const haptics::TissueModel& model, int layer) {
  return layer < 0 ? "" : model.layer(layer).name;
}

nlohmann::json run_json(const haptics::TissueModel& model, const haptics::InsertionRun& run,
                        const std::vector<haptics::LayerBoundary>& boundaries,
                        const haptics::SyringeInsertionRun* syringe) {
  nlohmann::json samples = nlohmann::json::array(), punctures = nlohmann::json::array(), rest = nlohmann::json::array();
  for (size_t k = 0; k < run.samples.size(); ++k) {
    const auto& s = run.samples[k];
    samples.push_back({{"t", s.t},
                       {"depth_m", s.depth_m},
                       {"axial_force_N", s.axial_force_N},
                       {"layer", layer_name(model, s.layer)}});
    if (syringe) {
      samples.back()["plunger_pressure_Pa"] = syringe->samples[k].pressure_Pa;
      samples.back()["plunger_travel_m"] = syringe->samples[k].travel_m;
    }
  }
  for (const auto& p : run.punctures)
    punctures.push_back(
        {{"layer", layer_name(model, p.layer)}, {"depth_m", p.depth_m}, {"peak_force_N", p.peak_force_N}});
  for (const auto& b : boundaries) rest.push_back({{"depth_m", b.depth_m}, {"layer", layer_name(model, b.layer)}});
  nlohmann::json stop = nullptr;
  if (run.hard_stop) stop = {{"layer", layer_name(model, run.hard_stop->layer)}, {"depth_m", run.hard_stop->depth_m}};
  nlohmann::json out = {{"samples", samples},
                        {"punctures", punctures},
                        {"tissue_work_J", run.tissue_work_J},
                        {"tick_us_median", run.tick_us_median},
                        {"hard_stop", stop},
                        {"boundaries", rest}};
  if (syringe) {
    nlohmann::json losses = nlohmann::json::array();
    for (const auto& l : syringe->losses)
      losses.push_back({{"depth_m", l.depth_m},
                        {"layer", layer_name(model, l.layer)},
                        {"pressure_before_Pa", l.pressure_before_Pa},
                        {"pressure_after_Pa", l.pressure_after_Pa}});
    out["loss_of_resistance"] = losses;
    out["plunger_work_J"] = syringe->work_J;
  }
  return out;
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

int run(const InsertionFlags& f) {
  if (f.from.size() != 3) throw UsageError("--from: expected three numbers X,Y,Z");
  if (f.dir.size() != 3) throw UsageError("--dir: expected three numbers DX,DY,DZ");
  const Eigen::Vector3d from_world(f.from[0], f.from[1], f.from[2]);
  const Eigen::Vector3d dir(f.dir[0], f.dir[1], f.dir[2]);
  const double depth = *f.depth, speed = *f.speed, hold = f.hold;
  if (dir.norm() < 1e-12) throw UsageError("--dir: must not be the zero vector");
  if (2.0 * depth / speed + hold > io::kMaxSessionSeconds)
    throw UsageError("--depth, --speed, --hold: the drive would last " + std::to_string(2.0 * depth / speed + hold) +
                     " s, over the " + std::to_string(int(io::kMaxSessionSeconds)) +
                     " s a run may (2 depth / speed + hold)");
  const std::string& scenario_path = *f.scenario;
  const auto& json_path = f.json;
  const auto& plot_path = f.plot;

  const haptics::Scenario scenario = haptics::load_scenario(scenario_path);
  if (scenario.scene.tissue.empty()) throw UsageError("--scenario: " + scenario_path + " has no tissue");
  haptics::InsertionPlan plan;
  plan.from = from_world - scenario.base_in_world;  // the scenario's tissue is in the robots' base frame
  plan.dir = dir.normalized();
  plan.depth_m = depth;
  plan.speed_mps = speed;
  plan.hold_s = hold;
  plan.period_s = scenario.period_s;
  if (f.syringe.empty() != !f.plunger_force)
    throw UsageError(f.syringe.empty() ? "--plunger-force: given without --syringe"
                                       : "--syringe: needs --plunger-force N");
  std::optional<haptics::SyringeInsertionRun> syringe;
  if (!f.syringe.empty()) {
    haptics::SyringeDrive drive{scenario.syringe.value_or(haptics::SyringeParams{}), *f.plunger_force};
    drive.params.fluid = *haptics::parse_syringe_fluid(f.syringe.c_str());
    for (const haptics::TissueLayer& layer : scenario.scene.tissue.layers())
      if (!layer.mechanics.rigid && !layer.injection)
        throw UsageError("--syringe: " + scenario_path + ": layer \"" + layer.name + "\" has no injection parameters");
    syringe = haptics::run_syringe_insertion(scenario.scene.tissue, plan, drive);
  }
  const haptics::InsertionRun run =
      syringe ? syringe->insertion : haptics::run_kinematic_insertion(scenario.scene.tissue, plan);
  // The layers along the line as far as the tip went (and the rigid surface that stopped it).
  const double reached = run.hard_stop ? std::min(depth, run.hard_stop->depth_m + 1e-3) : depth;
  const auto boundaries = haptics::layer_boundaries(scenario.scene.tissue, plan.from, plan.dir, reached);

  BenchTable table({"layer", "depth_m", "peak_force_N"});
  for (const auto& p : run.punctures)
    table.add_row({layer_name(scenario.scene.tissue, p.layer), p.depth_m, p.peak_force_N});
  table.print("bench insertion: " + scenario.name + ", punctures (" + std::to_string(run.samples.size()) +
              " ticks of " + std::to_string(scenario.period_s * 1e3) + " ms)");
  if (run.hard_stop)
    std::printf("hard stop: %s at depth %.4g m (a rigid layer: the drive stops there)\n",
                layer_name(scenario.scene.tissue, run.hard_stop->layer).c_str(), run.hard_stop->depth_m);
  std::printf("tissue_work_J %.6g, tick_us_median %.4g\n", run.tissue_work_J, run.tick_us_median);
  if (syringe) {
    BenchTable losses({"layer", "depth_m", "pressure_before_Pa", "pressure_after_Pa"});
    for (const auto& l : syringe->losses)
      losses.add_row(
          {layer_name(scenario.scene.tissue, l.layer), l.depth_m, l.pressure_before_Pa, l.pressure_after_Pa});
    losses.print("losses of resistance: " + f.syringe + ", the thumb on the plunger with " +
                 std::to_string(*f.plunger_force) + " N");
    std::printf("plunger_work_J %.6g\n", syringe->work_J);
  }
  if (json_path)
    io::write_file(*json_path,
                   run_json(scenario.scene.tissue, run, boundaries, syringe ? &*syringe : nullptr).dump(1) + "\n");
  if (plot_path) {
    char title[160];
    std::snprintf(title, sizeof title, "%s: %.3g mm/s in, %.3g s held, out", scenario.name.c_str(), speed * 1e3, hold);
    write_plot(*plot_path, title, scenario.scene.tissue, run, boundaries);
  }
  return 0;
}

// The options of bench insertion, declared; what runs it once they are parsed.
Runner declare(CLI::App& app) {
  auto f = std::make_shared<InsertionFlags>();
  // A point or a direction in the world: metres, within a kilometre of the origin (a design bound).
  const NumberRange coordinate{-1000.0, 1000.0};
  add_text(app, "--scenario", f->scenario, "FILE",
           "a scenario with a tissue (assets/scenarios/*.json); only its tissue and period are used")
      ->required();
  add_number_list(app, "--from", f->from, coordinate, "X,Y,Z", "the tip's start, world frame (m)", 3)->required();
  add_number_list(app, "--dir", f->dir, coordinate, "DX,DY,DZ", "insertion direction (normalized)", 3)->required();
  add_number(app, "--depth", f->depth, kInsertionDepth_m, "M",
             "how far along dir the tip is driven (m); a rigid layer on the way stops it")
      ->required();
  add_number(app, "--speed", f->speed, kInsertionSpeed_mps, "MPS", "constant speed in and out (m/s)")->required();
  add_number(app, "--hold", f->hold, kInsertionHold_s, "S", "seconds held at the deepest point");
  add_choice(
      app, "--syringe", f->syringe, {"saline", "air"},
      "a loss-of-resistance syringe on the needle, its thumb pressing from the first layer that holds the plunger\n"
      "(the scenario's syringe, or the default one, with this fluid; docs/TISSUE.md, \"The syringe\")");
  add_number(app, "--plunger-force", f->plunger_force, kPlungerForce_N, "N",
             "the thumb's force on the plunger (with --syringe)");
  add_output_file(
      app, "--json", f->json, "OUT",
      "samples {t, depth_m, axial_force_N, layer} (with --syringe also plunger_pressure_Pa, plunger_travel_m),\n"
      "punctures {layer, depth_m, peak_force_N}, tissue_work_J, tick_us_median, hard_stop, boundaries (the\n"
      "layers along the line at rest); with --syringe loss_of_resistance {depth_m, layer, pressure_before_Pa,\n"
      "pressure_after_Pa} and plunger_work_J");
  add_output_file(app, "--plot", f->plot, "OUT.png", "force against depth with the layer boundaries");
  app.footer("The whole drive, in, held and out (2 depth / speed + hold), lasts at most " +
             std::to_string(int(io::kMaxSessionSeconds)) + " s of simulated time.");
  return [f] { return run(*f); };
}

const CommandRegistrar reg{
    {"bench insertion", "the tissue model's own force-depth curve along a line, in and out", declare}};

}  // namespace
}  // namespace needle::cli
