#include "app/needle_tracker.hpp"

#include <glm/gtc/quaternion.hpp>

namespace needle::app {

engine::NeedleLoad NeedleTracker::update(const haptics::ToolSnapshot& s) {
  engine::NeedleLoad load;
  load.tip = {s.needle_tip_m[0], s.needle_tip_m[1], s.needle_tip_m[2]};
  const auto axis = haptics::needle_axis(s);
  load.axis = glm::normalize(glm::dvec3(axis[0], axis[1], axis[2]));
  const glm::dvec3 force(s.environment_force_n[0], s.environment_force_n[1], s.environment_force_n[2]);

  switch (s.contact) {
    case haptics::ContactState::kFree:
      entry_.reset();
      load.contact = engine::NeedleContact::Free;
      break;
    case haptics::ContactState::kRigidSurface:
      // The penalty keeps the tip within micrometres of the surface, and the surface pushes back
      // along its normal.
      entry_.reset();
      load.contact = engine::NeedleContact::Touching;
      load.surface_point = load.tip;
      load.surface_normal = glm::length(force) > 0.0 ? glm::normalize(force) : -load.axis;
      load.normal_force_N = glm::length(force);
      break;
    case haptics::ContactState::kTissue: {
      if (!entry_) entry_ = load.tip;
      load.contact = engine::NeedleContact::Inserted;
      load.surface_point = *entry_;
      load.surface_normal = -load.axis;
      // The constraint holds the needle against sideways motion with Aᵀλ = λ₁ y₅ + λ₂ z₅ (thesis
      // 4.2); the tissue takes the opposite. Without multipliers, the lateral part of the force.
      glm::dvec3 on_needle = force - load.axis * glm::dot(force, load.axis);
      if (s.multiplier_count >= 2) {
        const double* q = s.needle_orientation;
        const glm::dquat frame(q[0], q[1], q[2], q[3]);
        on_needle = s.multipliers[0] * (frame * glm::dvec3(0, 1, 0)) + s.multipliers[1] * (frame * glm::dvec3(0, 0, 1));
      }
      load.lateral_force_on_tissue_N = -on_needle;
      break;
    }
  }
  return load;
}

}  // namespace needle::app
