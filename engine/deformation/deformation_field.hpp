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

#include "engine/deformation/kelvinlet.hpp"
#include "engine/tissue.hpp"

namespace needle::engine {

// Declared before DeformationField, whose defaulted == uses them (clang finds only those declared
// before it).
bool operator==(const ElasticMaterial& a, const ElasticMaterial& b);
bool operator==(const Kelvinlet& a, const Kelvinlet& b);

struct DeformationField {
  ElasticMaterial material;
  std::vector<Kelvinlet> loads;
  bool empty() const { return loads.empty(); }
  bool operator==(const DeformationField&) const = default;
};

DeformationField build_field(const NeedleLoad& load, const TissueParams& tissue);

struct DeformedVertex {
  glm::dvec3 position;
  glm::dvec3 normal;  // unit
};

// Rest vertex -> deformed vertex; the normal follows the field's Jacobian (n' ∝ (I + ∂u/∂x)^-T n).
DeformedVertex deform(const DeformationField& field, const glm::dvec3& rest_position, const glm::dvec3& rest_normal);

}  // namespace needle::engine
