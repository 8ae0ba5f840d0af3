// Regularized Kelvinlets (de Goes and James, "Regularized Kelvinlets: Sculpting Brushes based on
// Fundamental Solutions of Elasticity", SIGGRAPH 2017, eq. 6-8): the closed-form displacement of
// an infinite, homogeneous, isotropic linear-elastic medium under a force spread over a radius ε.
// No mesh and no solve. We multiply each by a smooth window that is 1 at the load and exactly 0
// beyond a support radius, so that a frame only touches the vertices near the needle
// (docs/DEFORMATION.md measures what the window changes).
#pragma once

#include <glm/glm.hpp>

#include "engine/tissue.hpp"

namespace needle::engine {

struct Kelvinlet {
  glm::dvec3 center{0.0};
  glm::dvec3 force{0.0};  // N, applied to the medium
  double epsilon = 0.01;  // regularization radius, m
  double support = 0.05;  // window radius, m: the displacement is exactly zero at and beyond it
};

// Displacement u(x) and its Jacobian ∂u/∂x (column j = ∂u/∂x_j).
struct KelvinletSample {
  glm::dvec3 displacement{0.0};
  glm::dmat3 jacobian{0.0};
};

KelvinletSample evaluate(const Kelvinlet& k, const ElasticMaterial& m, const glm::dvec3& x);

// u(center) = compliance * force: the window is 1 there and the r rᵀ term vanishes,
// so a load can be chosen to move its centre by an exact displacement.
double center_compliance(const ElasticMaterial& m, double epsilon);

}  // namespace needle::engine
