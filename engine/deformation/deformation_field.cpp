#include "engine/deformation/deformation_field.hpp"

#include <algorithm>

namespace needle::engine {

bool operator==(const ElasticMaterial& a, const ElasticMaterial& b) {
  return a.shear_modulus_Pa == b.shear_modulus_Pa && a.poisson_ratio == b.poisson_ratio;
}

bool operator==(const Kelvinlet& a, const Kelvinlet& b) {
  return a.center == b.center && a.force == b.force && a.epsilon == b.epsilon && a.support == b.support;
}

namespace {

glm::dvec3 field_at(const std::vector<Kelvinlet>& loads, const ElasticMaterial& m, const glm::dvec3& x) {
  glm::dvec3 u(0.0);
  for (const Kelvinlet& k : loads) u += evaluate(k, m, x).displacement;
  return u;
}

// Appends the load at `center` that makes the total field there equal `target`, given the
// loads already present (their windows and 1/r decay make them add, not replace).
void pin(DeformationField& field, const glm::dvec3& center, const glm::dvec3& target, const TissueParams& tissue) {
  glm::dvec3 missing = target - field_at(field.loads, field.material, center);
  if (missing == glm::dvec3(0.0)) return;  // a zero load would only cost a dispatch
  Kelvinlet k{center, missing / center_compliance(field.material, tissue.radius_m), tissue.radius_m,
              tissue.falloff * tissue.radius_m};
  field.loads.push_back(k);
}

}  // namespace

DeformationField build_field(const NeedleLoad& load, const TissueParams& tissue) {
  DeformationField field{tissue.material, {}};
  const double support = tissue.falloff * tissue.radius_m;
  if (load.contact == NeedleContact::Touching) {
    glm::dvec3 push = load.tip - load.surface_point;
    if (glm::dot(push, load.surface_normal) < 0.0) pin(field, load.surface_point, push, tissue);
  } else if (load.contact == NeedleContact::Inserted) {
    const double depth = glm::dot(load.tip - load.surface_point, load.axis);
    if (depth > 0.0 && tissue.lateral_loads > 0 && glm::length(load.lateral_force_on_tissue_N) > 0.0) {
      const glm::dvec3 per_load = load.lateral_force_on_tissue_N / double(tissue.lateral_loads);
      for (int i = 0; i < tissue.lateral_loads; ++i) {
        double s = depth * (double(i) + 0.5) / double(tissue.lateral_loads);  // evenly along the shaft
        field.loads.push_back({load.tip - load.axis * (depth - s), per_load, tissue.radius_m, support});
      }
    }
    // The entry point goes to where the shaft now crosses: the surface never lets go of the needle.
    glm::dvec3 on_shaft = load.tip + load.axis * glm::dot(load.surface_point - load.tip, load.axis);
    pin(field, load.surface_point, on_shaft - load.surface_point, tissue);
  }
  return field;
}

glm::dvec3 deformed_point(const NeedleLoad& load, const TissueParams& tissue, const glm::dvec3& rest) {
  const DeformationField field = build_field(load, tissue);
  return rest + field_at(field.loads, field.material, rest);
}

DeformedVertex deform(const DeformationField& field, const glm::dvec3& rest_position, const glm::dvec3& rest_normal) {
  glm::dvec3 u(0.0);
  glm::dmat3 jacobian(0.0);
  for (const Kelvinlet& k : field.loads) {
    KelvinletSample s = evaluate(k, field.material, rest_position);
    u += s.displacement;
    jacobian += s.jacobian;
  }
  glm::dvec3 n = glm::inverse(glm::transpose(glm::dmat3(1.0) + jacobian)) * rest_normal;
  return {rest_position + u, glm::normalize(n)};
}

}  // namespace needle::engine
