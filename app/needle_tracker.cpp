#include "app/needle_tracker.hpp"

#include <glm/gtc/quaternion.hpp>

namespace needle::app {
namespace {

glm::dvec3 vec(const double (&v)[3]) { return {v[0], v[1], v[2]}; }

// (snapshot, axis) => the needle's lateral push on the tissue. The constraint holds the needle
// against sideways motion with Aᵀλ = λ₁ y₅ + λ₂ z₅ (thesis 4.2); the tissue takes the opposite.
// Without multipliers, the lateral part of the environment force.
glm::dvec3 lateral_force_on_tissue(const haptics::ToolSnapshot& s, const glm::dvec3& axis) {
  const glm::dvec3 force = vec(s.environment_force_n);
  glm::dvec3 on_needle = force - axis * glm::dot(force, axis);
  if (s.multiplier_count >= 2) {
    const double* q = s.needle_orientation;
    const glm::dquat frame(q[0], q[1], q[2], q[3]);
    on_needle = s.multipliers[0] * (frame * glm::dvec3(0, 1, 0)) + s.multipliers[1] * (frame * glm::dvec3(0, 0, 1));
  }
  return -on_needle;
}

// (snapshot, load) => (load: touching a rigid surface). The penalty keeps the tip within
// micrometres of the surface, and the surface pushes back along its normal.
void touch_rigid(const haptics::ToolSnapshot& s, engine::NeedleLoad& load) {
  const glm::dvec3 force = vec(s.environment_force_n);
  load.contact = engine::NeedleContact::Touching;
  load.surface_point = load.tip;
  load.surface_normal = glm::length(force) > 0.0 ? glm::normalize(force) : -load.axis;
  load.normal_force_N = glm::length(force);
}

}  // namespace

engine::NeedleLoad NeedleTracker::update(const haptics::ToolSnapshot& s) {
  engine::NeedleLoad load;
  load.tip = vec(s.needle_tip_m);
  const auto axis = haptics::needle_axis(s);
  load.axis = glm::normalize(glm::dvec3(axis[0], axis[1], axis[2]));

  if (kind_ == TissueKind::Layered) {
    const haptics::TissueSnapshot& t = s.tissue;
    if (t.punctured_layers != 0) {
      // Inserted: the entry is where the first surface gave way. In the tick it gives way the
      // snapshot still names it (a surface-less layer: the point where the tip crossed into it).
      if (!entry_) entry_ = t.surface_layer >= 0 ? vec(t.surface_point_m) : pressed_.value_or(load.tip);
      pressed_.reset();
      load.contact = engine::NeedleContact::Inserted;
      load.surface_point = *entry_;
      load.surface_normal = -load.axis;
      if (s.contact == haptics::ContactState::kTissue)
        load.lateral_force_on_tissue_N = lateral_force_on_tissue(s, load.axis);
      return load;
    }
    entry_.reset();
    if (t.surface_layer >= 0 && t.bone_layer < 0) {
      // Pressing a soft surface: the dimple from the rest point where the tip met it to the tip,
      // whose depth along the needle is the model's deflection. The surface is pushed along the
      // needle, so that is the direction it faces here.
      pressed_ = vec(t.surface_point_m);
      load.contact = engine::NeedleContact::Touching;
      load.surface_point = *pressed_;
      load.surface_normal = -load.axis;
      load.normal_force_N = t.axial_force_N;
      return load;
    }
    pressed_.reset();
    if (s.contact == haptics::ContactState::kRigidSurface) touch_rigid(s, load);
    return load;
  }

  switch (s.contact) {
    case haptics::ContactState::kFree:
      entry_.reset();
      load.contact = engine::NeedleContact::Free;
      break;
    case haptics::ContactState::kRigidSurface:
      entry_.reset();
      touch_rigid(s, load);
      break;
    case haptics::ContactState::kTissue:
      if (!entry_) entry_ = load.tip;
      load.contact = engine::NeedleContact::Inserted;
      load.surface_point = *entry_;
      load.surface_normal = -load.axis;
      load.lateral_force_on_tissue_N = lateral_force_on_tissue(s, load.axis);
      break;
  }
  return load;
}

}  // namespace needle::app
