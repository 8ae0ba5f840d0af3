#include "engine/deformation/kelvinlet.hpp"

#include <cmath>
#include <numbers>

namespace needle::engine {

double ElasticMaterial::a() const { return 1.0 / (4.0 * std::numbers::pi * shear_modulus_Pa); }
double ElasticMaterial::b() const { return a() / (4.0 * (1.0 - poisson_ratio)); }

double center_compliance(const ElasticMaterial& m, double epsilon) {
  // (a − b)/ε + a ε² / (2 ε³)
  return (1.5 * m.a() - m.b()) / epsilon;
}

KelvinletSample evaluate(const Kelvinlet& k, const ElasticMaterial& m, const glm::dvec3& x) {
  KelvinletSample s;
  const glm::dvec3 r = x - k.center;
  const double t = glm::dot(r, r);
  const double support2 = k.support * k.support;
  if (t >= support2) return s;

  const double a = m.a(), b = m.b(), eps2 = k.epsilon * k.epsilon;
  const double re2 = t + eps2, re = std::sqrt(re2), re3 = re2 * re, re5 = re3 * re2;
  // v = (A I + B r rᵀ) f with A = (a − b)/r_ε + a ε²/(2 r_ε³), B = b / r_ε³  (r_ε² = |r|² + ε²)
  const double A = (a - b) / re + a * eps2 / (2.0 * re3);
  const double B = b / re3;
  // Derivatives with respect to t = |r|² (∇t = 2 r).
  const double A_t = -(a - b) / (2.0 * re3) - 3.0 * a * eps2 / (4.0 * re5);
  const double B_t = -1.5 * b / re5;
  const double r_dot_f = glm::dot(r, k.force);
  const glm::dvec3 v = A * k.force + B * r_dot_f * r;
  // Window w = (1 − t/R²)²: 1 at the centre, zero value and slope at the support radius.
  const double q = 1.0 - t / support2;
  const double w = q * q;
  const double w_t = -2.0 * q / support2;

  const glm::dmat3 dv = 2.0 * A_t * glm::outerProduct(k.force, r) + 2.0 * B_t * r_dot_f * glm::outerProduct(r, r) +
                        B * (r_dot_f * glm::dmat3(1.0) + glm::outerProduct(r, k.force));
  s.displacement = w * v;
  s.jacobian = 2.0 * w_t * glm::outerProduct(v, r) + w * dv;
  return s;
}

}  // namespace needle::engine
