// Marker geometry shared by the progress tracker, the scoring and the guidance drawing.
#include "training/tasks/task.hpp"

#include <algorithm>

#include "io/input_limits.hpp"

namespace needle::training {

double session_time_bound_s(const Task& task) {
  double total = kTaskEndMargin_s;
  for (const Step& step : task.steps) {
    if (step.time_limit_s <= 0.0) return io::kMaxSessionSeconds;
    total += step.time_limit_s;
  }
  return std::min(total, io::kMaxSessionSeconds);
}

int interspace_at(const PatientLandmarks& l, const Vec3& p) {
  for (int k = 0; k < PatientLandmarks::kInterspaces; ++k)
    if (p[1] <= l.spinous_tips[size_t(k)][1] && p[1] > l.spinous_tips[size_t(k + 1)][1]) return k;
  return -1;
}

const char* interspace_name(int index) {
  static constexpr const char* kNames[] = {"L1-L2", "L2-L3", "L3-L4", "L4-L5", "L5-S1"};
  return index >= 0 && index < PatientLandmarks::kInterspaces ? kNames[index] : "none";
}

int interspace_index(const std::string& name) {
  for (int i = 0; i < PatientLandmarks::kInterspaces; ++i)
    if (name == interspace_name(i)) return i;
  return -1;
}

Task practice_task(Task task) {
  for (Step& step : task.steps) step.time_limit_s = 0.0;
  task.practice = true;
  return task;
}

ScoreMeasures score_measures(const Task& task) {
  ScoreMeasures m{false, false, false, false};
  for (const Step& s : task.steps) {
    m.tip_error = m.tip_error || s.condition.type == ConditionType::kTargetReached || s.guidance.target >= 0;
    m.axis_deviation = m.axis_deviation || s.condition.type == ConditionType::kAxisAligned || s.guidance.axis >= 0;
    m.force_steadiness = m.force_steadiness || s.condition.type == ConditionType::kForceHeld;
  }
  m.lateral_load = std::any_of(task.layers.begin(), task.layers.end(), [](const TaskLayer& l) { return !l.rigid; });
  return m;
}

int Task::marker_index(const std::string& marker_name) const {
  for (size_t i = 0; i < markers.size(); ++i)
    if (markers[i].name == marker_name) return static_cast<int>(i);
  return -1;
}

int Task::layer_index(const std::string& layer_name) const {
  for (size_t i = 0; i < layers.size(); ++i)
    if (layers[i].name == layer_name) return static_cast<int>(i);
  return -1;
}

namespace {

// Outward unit normal of the marker's sphere at the surface point nearest `tip` (the tip at the
// centre itself has no nearest point: take +z there rather than divide by zero).
Vec3 outward_normal(const Marker& sphere, const Vec3& tip) {
  const Vec3 r = tip - sphere.position;
  const double n = norm(r);
  return n > 1e-12 ? (1.0 / n) * r : Vec3{0.0, 0.0, 1.0};
}

}  // namespace

Vec3 planned_direction(const Marker& marker, const Vec3& tip) {
  if (marker.kind == MarkerKind::kSurfaceNormal) return -1.0 * outward_normal(marker, tip);
  return marker.direction;
}

std::array<Vec3, 3> normal_marker_positions(const Task& task, const Marker& surface, const Vec3& tip) {
  const Vec3 n = outward_normal(surface, tip);
  const Vec3 contact = surface.position + surface.radius_m * n;
  std::array<Vec3, 3> out;
  for (int k = 0; k < 3; ++k) out[k] = contact + ((k + 1) * task.normal_marker_spacing_m) * n;
  return out;
}

}  // namespace needle::training
