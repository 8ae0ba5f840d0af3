#include "training/sessions/force_depth.hpp"

#include <algorithm>
#include <cmath>

namespace needle::training {

ForceDepth force_depth(const std::vector<haptics::TickSample>& samples, const Task* task) {
  ForceDepth out;
  out.plot = {"Force along the needle against depth", "N", "depth (mm)", {}, {}, {}};
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
    }
    const double depth = 1000.0 * dot(tip - origin, axis);
    depth_at[i] = depth;
    Series& line = out.plot.lines.back();
    if (line.t.empty() || std::abs(depth - line.t.back()) >= kDepthStep_mm ||
        std::abs(t.axial_force_N - line.v.back()) >= kForceStep_N) {
      line.t.push_back(depth);
      line.v.push_back(t.axial_force_N);
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
  return out;
}

}  // namespace needle::training
