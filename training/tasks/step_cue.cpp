#include "training/tasks/step_cue.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "training/tasks/condition.hpp"

namespace needle::training {
namespace {

constexpr double kDeg = 180.0 / std::numbers::pi;

std::string format(const char* pattern, double a, double b = 0.0, double c = 0.0) {
  char text[160];
  std::snprintf(text, sizeof text, pattern, a, b, c);
  return text;
}

// A marker as the trainee knows it: by its role in the step's guidance, else by its name.
std::string point_name(const Task& task, const Step& step, int marker) {
  if (marker == step.guidance.entry) return "entry";
  if (marker == step.guidance.target) return "target";
  std::string name = task.markers[size_t(marker)].name;
  for (char& c : name)
    if (c == '_') c = ' ';
  return name;
}

std::string layer_name(const Task& task, int layer) {
  if (task.hide_layer_names || layer < 0 || size_t(layer) >= task.layers.size())
    return "layer " + std::to_string(layer + 1);
  return task.layers[size_t(layer)].name;
}

// "8 mm left" for a signed distance along a direction named by its two ends; "" under half a millimetre.
std::string along(double metres, const char* plus, const char* minus) {
  const double mm = metres * 1000.0;
  if (std::abs(mm) < 0.5) return "";
  return format("%.0f mm ", std::abs(mm)) + (mm > 0 ? plus : minus);
}

void append(std::string& list, const std::string& part) {
  if (part.empty()) return;
  list += (list.empty() ? "" : ", ") + part;
}

std::string point_line(const Task& task, const Step& step, const StepCue& cue) {
  std::string parts;
  append(parts, along(cue.to_point_view[0], "right", "left"));
  append(parts, along(cue.to_point_view[1], "up", "down"));
  append(parts, along(cue.to_point_view[2], "away from you", "towards you"));
  return point_name(task, step, cue.point) + format(" %.1f mm away", cue.distance_m * 1000.0) +
         (parts.empty() ? "" : ": " + parts);
}

std::string axis_line(const StepCue& cue) {
  const bool aligned = !std::isnan(cue.within_deg) && cue.off_axis_deg <= cue.within_deg;
  std::string line = format("off the axis %.0f deg", cue.off_axis_deg);
  if (aligned) return line + format(": on it (within %.0f deg)", cue.within_deg);
  std::string parts;
  if (std::abs(cue.turn_deg) >= 1.0)
    append(parts, format(cue.turn_deg > 0 ? "turn clockwise %.0f deg" : "turn anticlockwise %.0f deg",
                         std::abs(cue.turn_deg)));
  if (std::abs(cue.tilt_deg) >= 1.0)
    append(parts, format(cue.tilt_deg > 0 ? "tilt the hub away %.0f deg" : "tilt the hub towards you %.0f deg",
                         std::abs(cue.tilt_deg)));
  return parts.empty() ? line : line + ": " + parts;
}

std::string depth_line(const Task& task, const StepCue& cue) {
  const double mm = cue.depth_m * 1000.0;
  if (std::isnan(cue.band_min_m)) {
    if (task.markers[size_t(cue.gauge)].kind == MarkerKind::kSurfaceNormal)
      return mm < 0 ? format("%.0f mm above the surface", -mm) : format("%.0f mm under the surface", mm);
    return format("depth %.0f mm along the planned axis", mm);
  }
  const double lo = cue.band_min_m * 1000.0, hi = cue.band_max_m * 1000.0;
  if (mm < lo)
    return format("depth %.0f mm: %.0f mm deeper", mm, lo - mm) + format(" to the band (%.0f-%.0f mm)", lo, hi);
  if (mm > hi)
    return format("depth %.0f mm: %.0f mm back", mm, mm - hi) + format(" to the band (%.0f-%.0f mm)", lo, hi);
  return format("depth %.0f mm: in the band (%.0f-%.0f mm)", mm, lo, hi);
}

const char* contact_words(ContactRequirement c) {
  switch (c) {
    case ContactRequirement::kRigidSurface:
      return ", on the surface";
    case ContactRequirement::kTissue:
      return ", in the tissue";
    case ContactRequirement::kFree:
      return ", out of contact";
    case ContactRequirement::kAny:
      break;
  }
  return "";
}

}  // namespace

std::string condition_words(const Task& task, const Step& step) {
  const Condition& c = step.condition;
  std::string words;
  switch (c.type) {
    case ConditionType::kTipNear:
      words = format("the tip within %.0f mm of the ", c.within_m * 1000.0) + point_name(task, step, c.marker);
      break;
    case ConditionType::kAxisAligned:
      words = format("the needle within %.0f deg of the planned axis", c.within_rad * kDeg);
      break;
    case ConditionType::kDepthInBand:
      words = format("the tip %.0f-%.0f mm deep along the planned axis", c.min * 1000.0, c.max * 1000.0);
      break;
    case ConditionType::kForceHeld:
      words = format("a force of %.1f-%.1f N", c.min, c.max);
      break;
    case ConditionType::kTargetReached:
      words = format("the tip within %.0f mm of the target", c.within_m * 1000.0);
      break;
    case ConditionType::kWithdrawn:
      words = format("the needle out, over %.0f mm from the ", c.within_m * 1000.0) + point_name(task, step, c.marker);
      break;
    case ConditionType::kTipInLayer:
      words = "the tip in the " + layer_name(task, c.layer);
      break;
    case ConditionType::kPunctured:
      words = "the " + layer_name(task, c.layer) + " punctured";
      break;
    case ConditionType::kInterspaceEntered:
      words = std::string("the needle in through the skin over the ") + interspace_name(c.interspace) +
              " interspace, near the midline";
      break;
  }
  if (c.type != ConditionType::kWithdrawn) words += contact_words(c.contact);
  if (c.hold_s > 0.0) words += format(", held %.1f s", c.hold_s);
  return words;
}

int gauge_marker(const Task& task, size_t step) {
  const auto usable = [&](int m) {
    return m >= 0 && (task.markers[size_t(m)].kind == MarkerKind::kAxis ||
                      task.markers[size_t(m)].kind == MarkerKind::kSurfaceNormal);
  };
  for (size_t k = step + 1; k-- > 0;) {
    const Step& s = task.steps[k];
    if (k == step && s.condition.type == ConditionType::kDepthInBand) return s.condition.marker;
    for (int m : {s.guidance.depth_gauge, s.guidance.axis})
      if (usable(m)) return m;
  }
  for (size_t m = 0; m < task.markers.size(); ++m)
    if (usable(int(m))) return int(m);
  return -1;
}

double gauge_depth(const Marker& marker, const Vec3& tip) {
  if (marker.kind == MarkerKind::kSurfaceNormal) return marker.radius_m - distance(tip, marker.position);
  return depth_along(marker, tip);
}

StepCue step_cue(const Task& task, size_t step_index, const haptics::ToolSnapshot& state, const ViewAxes& view) {
  const Step& step = task.steps.at(step_index);
  const Condition& c = step.condition;
  const Vec3 tip = vec3(state.needle_tip_m);
  StepCue cue;
  if (c.type == ConditionType::kTipNear || c.type == ConditionType::kTargetReached) {
    cue.point = c.marker;
    const Vec3 to = task.markers[size_t(c.marker)].position - tip;
    cue.distance_m = norm(to);
    cue.to_point_view = {dot(to, view.right), dot(to, view.up), dot(to, view.forward)};
  }
  cue.axis = c.type == ConditionType::kAxisAligned ? c.marker : step.guidance.axis;
  if (cue.axis >= 0) {
    if (c.type == ConditionType::kAxisAligned) cue.within_deg = c.within_rad * kDeg;
    const auto a = haptics::needle_axis(state);
    const Vec3 now{a[0], a[1], a[2]}, wanted = planned_direction(task.markers[size_t(cue.axis)], tip);
    cue.off_axis_deg = angle_between(now, wanted) * kDeg;
    // The wrist's two angles from the needle now to the planned direction (haptics::wrist_direction's
    // terms): the tilt changes the angle to the view's direction, the swing turns about it.
    const Vec3& away = view.forward;
    cue.tilt_deg = (std::acos(std::clamp(dot(wanted, away) / norm(wanted), -1.0, 1.0)) -
                    std::acos(std::clamp(dot(now, away) / norm(now), -1.0, 1.0))) *
                   kDeg;
    const Vec3 p0 = now - dot(now, away) * away, p = wanted - dot(wanted, away) * away;
    cue.turn_deg = std::atan2(dot(cross(p0, p), away), dot(p0, p)) * kDeg;
  }
  cue.gauge = gauge_marker(task, step_index);
  if (cue.gauge >= 0) {
    cue.depth_m = gauge_depth(task.markers[size_t(cue.gauge)], tip);
    if (c.type == ConditionType::kDepthInBand) cue.band_min_m = c.min, cue.band_max_m = c.max;
  }
  return cue;
}

std::vector<std::string> cue_lines(const Task& task, size_t step_index, const haptics::ToolSnapshot& state,
                                   const StepCue& cue) {
  const Step& step = task.steps.at(step_index);
  const Condition& c = step.condition;
  std::vector<std::string> lines;
  switch (c.type) {
    case ConditionType::kForceHeld: {
      const double force = norm(vec3(state.environment_force_n));
      const char* what = force < c.min ? "press harder" : force > c.max ? "press lighter" : "in the band, hold it";
      lines.push_back(format("force %.1f N: ", force) + what + format(" (%.1f-%.1f N)", c.min, c.max));
      break;
    }
    case ConditionType::kTipInLayer:
      lines.push_back(
          "tip in " +
          (state.tissue.tip_layer < 0 ? std::string("no layer") : layer_name(task, state.tissue.tip_layer)) +
          (state.tissue.tip_layer == c.layer ? ": there, hold it"
                                             : "; the step wants it in " + layer_name(task, c.layer)));
      break;
    case ConditionType::kPunctured:
      lines.push_back("push on until the " + layer_name(task, c.layer) + " gives");
      break;
    case ConditionType::kWithdrawn:
      if (state.contact != haptics::ContactState::kFree)
        lines.push_back(state.contact == haptics::ContactState::kTissue ? "pull the needle out of the tissue"
                                                                        : "lift the tip off the surface");
      else if (const double d = distance(vec3(state.needle_tip_m), task.markers[size_t(c.marker)].position);
               d <= c.within_m)
        lines.push_back(format("move the tip %.0f mm further away", (c.within_m - d) * 1000.0));
      break;
    default:
      break;
  }
  if (cue.point >= 0) lines.push_back(point_line(task, step, cue));
  if (cue.axis >= 0) lines.push_back(axis_line(cue));
  if (cue.gauge >= 0 && (c.type == ConditionType::kDepthInBand || step.guidance.depth_gauge >= 0))
    lines.push_back(depth_line(task, cue));
  return lines;
}

}  // namespace needle::training
