#include "training/tasks/condition.hpp"

#include <cmath>

namespace needle::training {

bool contact_matches(ContactRequirement required, haptics::ContactState contact) {
  switch (required) {
    case ContactRequirement::kAny:
      return true;
    case ContactRequirement::kFree:
      return contact == haptics::ContactState::kFree;
    case ContactRequirement::kRigidSurface:
      return contact == haptics::ContactState::kRigidSurface;
    case ContactRequirement::kTissue:
      return contact == haptics::ContactState::kTissue;
  }
  return false;
}

double depth_along(const Marker& axis, const Vec3& tip) { return dot(tip - axis.position, axis.direction); }

bool condition_holds(const Task& task, const Condition& c, const haptics::ToolSnapshot& state) {
  if (!contact_matches(c.contact, state.contact)) return false;
  const Vec3 tip = vec3(state.needle_tip_m);
  switch (c.type) {
    case ConditionType::kTipNear:
    case ConditionType::kTargetReached:
      return distance(tip, task.markers[c.marker].position) <= c.within_m;
    case ConditionType::kWithdrawn:
      return distance(tip, task.markers[c.marker].position) > c.within_m;
    case ConditionType::kAxisAligned:
      return angle_between(haptics::needle_axis(state), planned_direction(task.markers[c.marker], tip)) <= c.within_rad;
    case ConditionType::kDepthInBand: {
      const double depth = depth_along(task.markers[c.marker], tip);
      return depth >= c.min && depth <= c.max;
    }
    case ConditionType::kTipInLayer:
      return state.tissue.tip_layer == c.layer;
    case ConditionType::kPunctured:
      return haptics::punctured(state.tissue, c.layer);
    case ConditionType::kInterspaceEntered: {
      // In tissue, between the interspace's spinous processes along the spine, near the midline.
      if (!task.landmarks || state.contact != haptics::ContactState::kTissue) return false;
      const PatientLandmarks& l = *task.landmarks;
      return interspace_at(l, tip) == c.interspace &&
             std::abs(tip[0] - l.entries[size_t(c.interspace)][0]) <= kInterspaceHalfWidth_m;
    }
    case ConditionType::kForceHeld: {
      const double force = norm(vec3(state.environment_force_n));
      return force >= c.min && force <= c.max;
    }
  }
  return false;
}

}  // namespace needle::training
