#include "engine/scripted_needle.hpp"

#include <algorithm>
#include <cmath>

namespace needle::engine {
namespace {

// 0 before t0, 1 after t1, smooth in between.
double ramp(double t, double t0, double t1) {
  double s = std::clamp((t - t0) / (t1 - t0), 0.0, 1.0);
  return s * s * (3.0 - 2.0 * s);
}

constexpr double kDimple_m = 0.008, kFirstDepth_m = 0.03, kSecondDepth_m = 0.045, kApproach_m = 0.04;
constexpr double kPivot_rad = 0.7853981633974483;  // 45°, as in the thesis
constexpr double kLateral_N = 1.5;

}  // namespace

NeedleLoad scripted_needle(const ScriptedSphere& sphere, double t_s) {
  const double t = std::fmod(std::fmod(t_s, kScriptPeriod_s) + kScriptPeriod_s, kScriptPeriod_s);
  const glm::dvec3 n = glm::normalize(sphere.entry_direction);
  const glm::dvec3 side = glm::normalize(sphere.pivot_towards - n * glm::dot(sphere.pivot_towards, n));
  NeedleLoad load;
  load.surface_point = sphere.centre + sphere.radius * n;
  load.surface_normal = n;
  load.axis = -n;
  if (t < 2.0) {  // approach along the normal
    load.contact = NeedleContact::Free;
    load.tip = load.surface_point + n * (kApproach_m * (1.0 - ramp(t, 0.0, 2.0)));
  } else if (t < 3.0) {  // press a dimple
    load.contact = NeedleContact::Touching;
    load.tip = load.surface_point - n * (kDimple_m * ramp(t, 2.0, 3.0));
  } else if (t < 9.5) {  // punctured: insert, pivot about the tip, insert deeper
    load.contact = NeedleContact::Inserted;
    const double pivot = kPivot_rad * ramp(t, 5.0, 8.0);
    // At puncture the tip is where the dimple took it; the tissue closes around the shaft.
    const glm::dvec3 first_tip = load.surface_point - n * (kDimple_m + (kFirstDepth_m - kDimple_m) * ramp(t, 3.0, 5.0));
    load.axis = std::cos(pivot) * -n + std::sin(pivot) * side;
    load.tip = first_tip + load.axis * ((kSecondDepth_m - kFirstDepth_m) * ramp(t, 8.0, 9.5));
    // The tissue resists the shaft sweeping sideways while it pivots.
    load.lateral_force_on_tissue_N = side * (kLateral_N * std::sin(pivot) * (1.0 - ramp(t, 8.0, 9.5)));
  } else {  // withdraw along the axis, then glide back to where the approach starts
    const glm::dvec3 axis = std::cos(kPivot_rad) * -n + std::sin(kPivot_rad) * side;
    const glm::dvec3 deepest = load.surface_point - n * kFirstDepth_m + axis * (kSecondDepth_m - kFirstDepth_m);
    const glm::dvec3 withdrawn = deepest - axis * (ramp(t, 9.5, 11.5) * (kSecondDepth_m + 0.02));
    const double back = ramp(t, 11.5, kScriptPeriod_s);
    load.tip = glm::mix(withdrawn, load.surface_point + n * kApproach_m, back);
    load.axis = glm::normalize(glm::mix(axis, -n, back));
    const bool inside = glm::dot(load.tip - load.surface_point, n) < 0.0;
    load.contact = inside ? NeedleContact::Inserted : NeedleContact::Free;
  }
  return load;
}

}  // namespace needle::engine
