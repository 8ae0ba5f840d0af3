// The tissue displacement field for one frame, built from the needle's state: a sum of windowed
// regularized Kelvinlets (kelvinlet.hpp). Before puncture, one load at the contact point is
// chosen so that the surface there follows the tip exactly (the dimple); once inserted, one at
// the entry point keeps the surface on the shaft wherever the needle pivots, and loads along
// the inserted shaft carry the lateral constraint force into the tissue. The field depends on
// the current state only, so the surface is back at rest as soon as the needle leaves.
// This CPU version, in double precision, is the reference for the GPU pass.
#pragma once

#include <glm/glm.hpp>
#include <vector>

#include "engine/kelvinlet.hpp"

namespace needle::engine {

// Per-tissue parameters, from the scene file.
struct TissueParams {
  ElasticMaterial material;
  double radius_m = 0.01;      // ε: how wide a load spreads (stiffness-like radius)
  double falloff = 5.0;        // support radius = falloff × ε
  int lateral_loads = 2;       // loads spreading the lateral force along the inserted shaft
};

enum class NeedleContact { Free, Touching, Inserted };

// What the haptic state says about the needle this frame, in world coordinates.
struct NeedleLoad {
  NeedleContact contact = NeedleContact::Free;
  glm::dvec3 tip{0.0};
  glm::dvec3 axis{1.0, 0.0, 0.0};  // unit, from hub to tip (the thesis's x5)
  // Touching: the point of the rest surface under the tip. Inserted: where the needle entered.
  glm::dvec3 surface_point{0.0};
  glm::dvec3 surface_normal{0.0, 0.0, 1.0};  // outward, at surface_point
  double normal_force_N = 0.0;               // λ on the surface before puncture (reported, not needed for shape)
  glm::dvec3 lateral_force_on_tissue_N{0.0};  // inserted: the needle's lateral push on the tissue
};

struct DeformationField {
  ElasticMaterial material;
  std::vector<Kelvinlet> loads;
  bool empty() const { return loads.empty(); }
  bool operator==(const DeformationField&) const = default;
};

bool operator==(const ElasticMaterial& a, const ElasticMaterial& b);
bool operator==(const Kelvinlet& a, const Kelvinlet& b);

DeformationField build_field(const NeedleLoad& load, const TissueParams& tissue);

struct DeformedVertex {
  glm::dvec3 position;
  glm::dvec3 normal;  // unit
};

// Rest vertex -> deformed vertex; the normal follows the field's Jacobian (n' ∝ (I + ∂u/∂x)^-T n).
DeformedVertex deform(const DeformationField& field, const glm::dvec3& rest_position, const glm::dvec3& rest_normal);

}  // namespace needle::engine
