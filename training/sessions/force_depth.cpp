#include "training/sessions/force_depth.hpp"

#include <algorithm>
#include <cmath>

#include "haptics/syringe/loss_of_resistance.hpp"

namespace needle::training {

ForceDepth force_depth(const std::vector<haptics::TickSample>& samples, const Task* task) {
  ForceDepth out;
  out.plot = {"Force along the needle against depth", "N", "depth (mm)", {}, {}, {}};
  out.pressure = {"Plunger pressure against depth", "kPa", "depth (mm)", {}, {}, {}};
  const bool syringe = task && task->syringe;
  if (!syringe) out.pressure.missing = task ? "task " + task->name + " has no syringe" : "no task";
  haptics::LossDetector losses;
  if (!task || task->layers.size() < 2) {
    out.plot.missing = task ? "task " + task->name + " has no layered tissue" : "no task to name the layers";
    return out;
  }
  if (samples.empty()) {
    out.plot.missing = "the recording has no samples";
    return out;
  }
  SessionScorer scorer(*task);
  std::vector<bool> entered(task->layers.size(), false);
  std::vector<double> depth_at(samples.size(), 0.0);
  bool on_track = false;
  Vec3 origin{}, axis{};
  for (size_t i = 0; i < samples.size(); ++i) {
    const haptics::ToolSnapshot& s = samples[i].state;
    scorer.feed(samples[i]);
    const bool loss = syringe && losses.add(s.time_s, s.syringe.flow_m3_per_s, s.syringe.pressure_Pa, s.syringe.layer,
                                            s.syringe.thumb_force_N);
    const haptics::TissueSnapshot& t = s.tissue;
    const bool touching = t.tip_layer >= 0 || t.surface_layer >= 0 || t.punctured_layers != 0;
    if (!touching) {
      on_track = false;
      continue;
    }
    const Vec3 tip = vec3(s.needle_tip_m);
    if (!on_track) {
      on_track = true;
      origin = tip;
      const auto a = haptics::needle_axis(s);
      axis = {a[0], a[1], a[2]};
      out.plot.lines.push_back({"track " + std::to_string(out.plot.lines.size() + 1), {}, {}});
      if (syringe) out.pressure.lines.push_back({out.plot.lines.back().name, {}, {}});
    }
    const double depth = 1000.0 * dot(tip - origin, axis);
    depth_at[i] = depth;
    Series& line = out.plot.lines.back();
    if (line.t.empty() || std::abs(depth - line.t.back()) >= kDepthStep_mm ||
        std::abs(t.axial_force_N - line.v.back()) >= kForceStep_N) {
      line.t.push_back(depth);
      line.v.push_back(t.axial_force_N);
    }
    if (syringe) {
      Series& p = out.pressure.lines.back();
      const double kPa = 1e-3 * s.syringe.pressure_Pa;
      if (p.t.empty() || std::abs(depth - p.t.back()) >= kDepthStep_mm ||
          std::abs(kPa - p.v.back()) >= kPressureStep_kPa || loss) {
        p.t.push_back(depth);
        p.v.push_back(kPa);
      }
      if (loss) {
        const int layer = losses.current().layer;
        const std::string name =
            layer >= 0 && size_t(layer) < task->layers.size() ? task->layers[size_t(layer)].name : "no layer";
        out.losses.push_back({depth, 1e-3 * losses.current().pressure_before_Pa,
                              layer == task->syringe->space ? name : name + " (false)"});
      }
    }
    if (t.tip_layer >= 0 && size_t(t.tip_layer) < entered.size() && !entered[size_t(t.tip_layer)]) {
      entered[size_t(t.tip_layer)] = true;
      out.boundaries.push_back({depth, 0.0, task->layers[size_t(t.tip_layer)].name});
    }
  }
  out.puncture_list = scorer.result().punctures;
  for (const PunctureResult& p : out.puncture_list) {
    // The state the puncture was scored on: the first at or after its time.
    const auto at = std::lower_bound(samples.begin(), samples.end(), p.t_s,
                                     [](const haptics::TickSample& s, double t) { return s.state.time_s < t; });
    if (at != samples.end()) out.punctures.push_back({depth_at[size_t(at - samples.begin())], p.peak_force_N, p.layer});
  }
  if (out.plot.lines.empty()) out.plot.missing = "the needle never met the tissue";
  if (syringe && out.pressure.lines.empty()) out.pressure.missing = out.plot.missing;
  return out;
}

}  // namespace needle::training
