#include "haptics/tissue/kinematic_insertion.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>

#include "haptics/tissue/tissue_step.hpp"

namespace needle::haptics {

std::optional<InsertionStop> first_rigid_surface(const TissueModel& model, const Eigen::Vector3d& start,
                                                 const Eigen::Vector3d& dir, double length) {
  constexpr double kHit = 1e-9;  // m
  double t = 0.0;
  for (int iteration = 0; iteration < 100000 && t <= length; ++iteration) {
    double nearest = std::numeric_limits<double>::infinity(), step = nearest;
    int layer = -1;
    for (int i = 0; i < model.layer_count(); ++i) {
      if (!model.layer(i).mechanics.rigid) continue;
      const LayerShape& shape = model.layer(i).shape;
      const double phi = shape.phi(start + t * dir);
      if (phi < nearest) nearest = phi, layer = i;
      step = std::min(step, phi / shape.lipschitz());
    }
    if (layer < 0) return std::nullopt;
    if (nearest < kHit) return InsertionStop{layer, t};
    t += step;
  }
  return std::nullopt;
}

std::vector<LayerBoundary> layer_boundaries(const TissueModel& model, const Eigen::Vector3d& start,
                                            const Eigen::Vector3d& dir, double length) {
  constexpr double kStep = 5e-5;  // m
  std::vector<LayerBoundary> boundaries;
  int layer = model.layer_at(start);
  for (double t0 = 0.0; t0 < length;) {
    const double t1 = std::min(t0 + kStep, length);
    const int next = model.layer_at(start + t1 * dir);
    if (next != layer) {
      double lo = t0, hi = t1;  // layer_at(lo) == layer, layer_at(hi) != layer
      for (int k = 0; k < 40; ++k) {
        const double mid = 0.5 * (lo + hi);
        (model.layer_at(start + mid * dir) == layer ? lo : hi) = mid;
      }
      boundaries.push_back({hi, next});
      layer = next;
    }
    t0 = t1;
  }
  return boundaries;
}

InsertionRun run_kinematic_insertion(const TissueModel& model, const InsertionPlan& plan,
                                     const InsertionTickObserver& observer) {
  if (!(plan.depth_m > 0.0) || !(plan.speed_mps > 0.0) || !(plan.period_s > 0.0) || !(plan.hold_s >= 0.0) ||
      !(plan.dir.norm() > 1e-12))
    throw std::invalid_argument("insertion plan: depth, speed and period must be > 0, hold >= 0, dir nonzero");
  const Eigen::Vector3d dir = plan.dir.normalized();
  const double step = plan.speed_mps * plan.period_s;  // depth per tick
  InsertionRun run;
  run.hard_stop = first_rigid_surface(model, plan.from, dir, plan.depth_m);
  const double reach = run.hard_stop ? run.hard_stop->depth_m : plan.depth_m;

  // The commanded depth: in at constant speed to depth_m (the drive stays at a rigid surface
  // once it reaches it), held, out at the same speed from where it stopped.
  const long in_ticks = long(std::ceil(plan.depth_m / step - 1e-9));
  const long hold_ticks = long(std::llround(plan.hold_s / plan.period_s));
  const long out_ticks = long(std::ceil(reach / step - 1e-9));
  const long ticks = in_ticks + hold_ticks + out_ticks + 1;
  auto depth_at = [&](long k) {
    if (k <= in_ticks) return std::min({double(k) * step, plan.depth_m, reach});
    if (k <= in_ticks + hold_ticks) return reach;
    return std::max(reach - double(k - in_ticks - hold_ticks) * step, 0.0);
  };

  run.samples.reserve(size_t(ticks));
  std::vector<double> tick_us(static_cast<size_t>(ticks));
  TissueState state;
  using Clock = std::chrono::steady_clock;
  for (long k = 0; k < ticks; ++k) {
    const double depth = depth_at(k);
    const Eigen::Vector3d tip = plan.from + depth * dir;
    const auto t0 = Clock::now();
    const TissueOutput& out = step_tissue(model, state, tip, dir, plan.period_s);
    tick_us[size_t(k)] = std::chrono::duration<double, std::micro>(Clock::now() - t0).count();
    run.samples.push_back({double(k) * plan.period_s, depth, out.axial_force_N, out.holding_layer});
    if (out.punctured_layer >= 0) run.punctures.push_back({out.punctured_layer, depth, out.axial_force_N});
    if (observer) observer(k, depth, out);
  }
  run.tissue_work_J = state.tissue_work_J;
  std::nth_element(tick_us.begin(), tick_us.begin() + long(tick_us.size() / 2), tick_us.end());
  run.tick_us_median = tick_us[tick_us.size() / 2];
  return run;
}

}  // namespace needle::haptics
