// What the engine's tissue deformation takes from outside: a deformable tissue's parameters (from
// its scene file) and the needle's state each frame. The field built from them, its GPU pass and
// its CPU reference are the engine's own (engine/deformation/, docs/DEFORMATION.md).
#pragma once

#include <glm/glm.hpp>

namespace needle::engine {

struct ElasticMaterial {
  double shear_modulus_Pa = 3000.0;  // μ; soft tissue is of the order of kPa
  double poisson_ratio = 0.45;       // ν; near 0.5 the medium bulges (volume kept)

  double a() const;  // 1 / (4 π μ)
  double b() const;  // a / (4 (1 − ν))
};

// Per-tissue parameters, from the scene file.
struct TissueParams {
  ElasticMaterial material;
  double radius_m = 0.01;  // ε: how wide a load spreads (stiffness-like radius)
  double falloff = 5.0;    // support radius = falloff × ε
  int lateral_loads = 2;   // loads spreading the lateral force along the inserted shaft
};

enum class NeedleContact { Free, Touching, Inserted };

// What the haptic state says about the needle this frame, in world coordinates.
struct NeedleLoad {
  NeedleContact contact = NeedleContact::Free;
  glm::dvec3 tip{0.0};
  glm::dvec3 axis{1.0, 0.0, 0.0};  // unit, from hub to tip (the thesis's x5)
  // Touching: the point of the rest surface under the tip. Inserted: where the needle entered.
  glm::dvec3 surface_point{0.0};
  glm::dvec3 surface_normal{0.0, 0.0, 1.0};   // outward, at surface_point
  double normal_force_N = 0.0;                // λ on the surface before puncture (reported, not needed for shape)
  glm::dvec3 lateral_force_on_tissue_N{0.0};  // inserted: the needle's lateral push on the tissue
};

// (needle load, tissue parameters, a rest point of the tissue) => where the deformation moves that
// point this frame, world frame: the double-precision CPU reference of the pass's field
// (docs/DEFORMATION.md), for checking what the application feeds it.
glm::dvec3 deformed_point(const NeedleLoad& load, const TissueParams& tissue, const glm::dvec3& rest);

}  // namespace needle::engine
