#include "training/sessions/session_series.hpp"

#include <algorithm>
#include <cmath>

#include "training/scoring/step_metrics.hpp"
#include "training/tasks/condition.hpp"

namespace needle::training {
namespace {

double norm3(const double (&v)[3]) { return norm(vec3(v)); }

// Joint-space devices share the virtual robot's geometry and are coupled joint to joint
// (docs/DEVICES.md); their commands are joint torques.
bool joint_space(const std::vector<haptics::TickSample>& samples) {
  return std::any_of(samples.begin(), samples.end(), [](const haptics::TickSample& s) {
    return s.command.space == haptics::CommandSpace::kJointTorque;
  });
}

double joint_tracking_mrad(const haptics::TickSample& s) {
  const uint32_t n = std::min({s.reading.joint_count, s.state.joint_count, uint32_t(haptics::kMaxSnapshotJoints)});
  double sum = 0.0;
  for (uint32_t j = 0; j < n; ++j) {
    const double e = s.reading.joint_rad[j] - s.state.virtual_q[j];
    sum += e * e;
  }
  return 1000.0 * std::sqrt(sum);
}

// One series per value function, sampled at every state.
template <class F>
Series series(const std::string& name, const std::vector<haptics::TickSample>& samples, F&& value) {
  Series out{name, {}, {}};
  out.t.reserve(samples.size());
  out.v.reserve(samples.size());
  for (const haptics::TickSample& s : samples) {
    out.t.push_back(s.state.time_s);
    out.v.push_back(value(s));
  }
  return out;
}

Plot depth_plot(const std::vector<haptics::TickSample>& samples, const Task* task) {
  Plot plot{"Depth along the insertion axis", "mm", "t (s)", {}, {}, {}};
  if (!task) {
    plot.missing = "no task to measure the depth against";
    return plot;
  }
  const int axis = insertion_axis_marker(*task);
  if (axis < 0) {
    plot.missing = "task " + task->name + " has no insertion axis (no depth_in_band step, no depth gauge)";
    return plot;
  }
  const Marker& marker = task->markers[size_t(axis)];
  std::string name = marker.name;  // the marker's name in words: "insertion axis"
  std::replace(name.begin(), name.end(), '_', ' ');
  plot.title = "Depth along the " + name;
  plot.lines.push_back(series("depth", samples, [&](const haptics::TickSample& s) {
    return 1000.0 * depth_along(marker, vec3(s.state.needle_tip_m));
  }));
  for (const Step& step : task->steps) {
    const Condition& c = step.condition;
    if (c.type != ConditionType::kDepthInBand || c.marker != axis) continue;
    plot.guides.push_back({1000.0 * c.min, step.id + " min"});
    plot.guides.push_back({1000.0 * c.max, step.id + " max"});
  }
  return plot;
}

}  // namespace

int insertion_axis_marker(const Task& task) {
  for (const Step& s : task.steps) {
    if (s.condition.type == ConditionType::kDepthInBand) return s.condition.marker;
  }
  for (const Step& s : task.steps) {
    if (s.guidance.depth_gauge >= 0) return s.guidance.depth_gauge;
  }
  return -1;
}

SessionPlots session_plots(const std::vector<haptics::TickSample>& samples, const Task* task) {
  SessionPlots p;
  p.force = {"Forces", "N", "t (s)", {}, {}, {}};
  p.lateral = {"Sideways load on the needle", "N", "t (s)", {}, {}, {}};
  p.tracking = {"How far the needle lags the hand (joint angles)", "mrad", "t (s)", {}, {}, {}};
  if (samples.empty()) {
    for (Plot* plot : {&p.force, &p.lateral, &p.depth, &p.tracking}) plot->missing = "the recording has no samples";
    p.depth.title = "Depth along the insertion axis";
    p.depth.unit = "mm";
    return p;
  }
  const double scale = task ? task->force_scale : 1.0;
  p.force.lines.push_back(
      series("force at the hand", samples, [scale](const auto& s) { return hand_force_N(s.state, scale); }));
  p.force.lines.push_back(
      series("force along the needle (tissue)", samples, [](const auto& s) { return s.state.tissue.axial_force_N; }));
  p.force.lines.push_back(series("force on bone or a rigid surface", samples,
                                 [](const auto& s) { return norm3(s.state.environment_force_n); }));
  p.force.lines.push_back(
      series("the hand's push (sensed)", samples, [](const auto& s) { return norm3(s.state.operator_force_n); }));
  if (task) p.force.guides.push_back({task->scoring.safe_force_N, "safe limit at the hand"});
  p.lateral.lines.push_back(
      series("sideways load on the needle", samples, [](const auto& s) { return lateral_load_N(s.state); }));
  p.depth = depth_plot(samples, task);
  if (joint_space(samples)) {
    p.tracking.lines.push_back(series("lag of the needle behind the hand", samples, joint_tracking_mrad));
  } else {
    // The recording holds neither the workspace scale, the device-to-scene rotation nor the
    // coupling stiffness, so the stretch in metres is not derivable; its force K * stretch is.
    p.tracking = {"How hard the hand pulls the needle along", "N", "t (s)", {}, {}, {}};
    p.tracking.lines.push_back(series("pull between the hand and the needle", samples,
                                      [](const auto& s) { return norm3(s.state.operator_force_n); }));
  }
  return p;
}

Series decimate(const Series& in, size_t bins) {
  if (bins == 0 || in.t.size() <= 2 * bins) return in;
  Series out{in.name, {}, {}};
  const double t0 = in.t.front(), span = in.t.back() - t0;
  size_t i = 0;
  for (size_t b = 0; b < bins; ++b) {
    const double end = t0 + span * double(b + 1) / double(bins);
    const size_t start = i;
    size_t lo = i, hi = i;
    for (; i < in.t.size() && (in.t[i] <= end || b + 1 == bins); ++i) {
      if (in.v[i] < in.v[lo]) lo = i;
      if (in.v[i] > in.v[hi]) hi = i;
    }
    if (i == start) continue;  // no sample fell in this bin
    for (size_t k : {std::min(lo, hi), std::max(lo, hi)}) {
      out.t.push_back(in.t[k]);
      out.v.push_back(in.v[k]);
      if (lo == hi) break;
    }
  }
  return out;
}

std::vector<double> axis_ticks(double lo, double hi, int max_ticks) {
  std::vector<double> ticks;
  if (!(hi > lo) || max_ticks < 1) return ticks;
  const double decade = std::pow(10.0, std::floor(std::log10((hi - lo) / max_ticks)));
  auto first = [&](double step) { return std::ceil(lo / step - 1e-9); };
  auto last = [&](double step) { return std::floor(hi / step + 1e-9); };
  double step = 100.0 * decade;  // one tick at most: always fits
  for (double m : {1.0, 2.0, 5.0, 10.0, 20.0, 50.0}) {
    if (last(m * decade) - first(m * decade) + 1.0 <= max_ticks) {
      step = m * decade;
      break;
    }
  }
  for (double k = first(step); k <= last(step); k += 1.0) ticks.push_back(k * step + 0.0);
  return ticks;
}

}  // namespace needle::training
