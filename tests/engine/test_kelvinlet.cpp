// Windowed regularized Kelvinlets against independent expectations: finite differences for the
// Jacobian, Kelvin's singular solution far from the load, zero divergence of an incompressible
// medium, and the window's exact zero at the support radius.
#include <gtest/gtest.h>

#include <numbers>
#include <random>

#include "engine/deformation/kelvinlet.hpp"

namespace needle::test {
namespace {

using engine::ElasticMaterial;
using engine::Kelvinlet;

glm::dvec3 random_in_ball(std::mt19937& rng, double radius) {
  std::uniform_real_distribution<double> d(-radius, radius);
  for (;;) {
    glm::dvec3 p(d(rng), d(rng), d(rng));
    if (glm::length(p) < radius) return p;
  }
}

TEST(Kelvinlet, JacobianMatchesCentralDifferences) {
  std::mt19937 rng(7);
  ElasticMaterial m{2500.0, 0.4};
  for (int trial = 0; trial < 50; ++trial) {
    Kelvinlet k{random_in_ball(rng, 0.05), random_in_ball(rng, 2.0), 0.004 + 0.01 * trial / 50.0, 0.05};
    glm::dvec3 x = k.center + random_in_ball(rng, 0.045);
    glm::dmat3 analytic = engine::evaluate(k, m, x).jacobian;
    const double h = 1e-7;
    for (int j = 0; j < 3; ++j) {
      glm::dvec3 dx(0.0);
      dx[j] = h;
      glm::dvec3 fd =
          (engine::evaluate(k, m, x + dx).displacement - engine::evaluate(k, m, x - dx).displacement) / (2 * h);
      for (int i = 0; i < 3; ++i) {
        EXPECT_NEAR(analytic[j][i], fd[i], 1e-6 * (1.0 + std::abs(fd[i])))
            << "trial " << trial << " d u" << i << "/dx" << j;
      }
    }
  }
}

TEST(Kelvinlet, FarFromASmallLoadItIsKelvinsSolution) {
  // Kelvin (1848): u = [(a − b)/r I + b/r³ r rᵀ] f, with a = 1/(4πμ), b = a/(4(1 − ν)).
  ElasticMaterial m{1000.0, 0.3};
  const double a = 1.0 / (4.0 * std::numbers::pi * 1000.0), b = a / (4.0 * 0.7);
  Kelvinlet k{glm::dvec3(0.0), glm::dvec3(0.3, -1.0, 2.0), 1e-6, 1e6};  // tiny ε, window far away
  glm::dvec3 r(0.02, 0.01, -0.03);
  double d = glm::length(r);
  glm::dvec3 kelvin = (a - b) / d * k.force + b / (d * d * d) * glm::dot(r, k.force) * r;
  glm::dvec3 u = engine::evaluate(k, m, r).displacement;
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(u[i], kelvin[i], 1e-6 * glm::length(kelvin));
}

TEST(Kelvinlet, IncompressibleMediumHasNoDivergence) {
  std::mt19937 rng(3);
  ElasticMaterial m{3000.0, 0.5};
  for (int trial = 0; trial < 20; ++trial) {
    Kelvinlet k{glm::dvec3(0.0), random_in_ball(rng, 1.0), 0.01, 1e6};  // window off
    glm::dmat3 j = engine::evaluate(k, m, random_in_ball(rng, 0.05)).jacobian;
    double scale = std::abs(j[0][0]) + std::abs(j[1][1]) + std::abs(j[2][2]) + 1e-12;
    EXPECT_NEAR(j[0][0] + j[1][1] + j[2][2], 0.0, 1e-12 * scale + 1e-15);
  }
}

TEST(Kelvinlet, CentreMovesByComplianceTimesForce) {
  ElasticMaterial m{3000.0, 0.45};
  Kelvinlet k{glm::dvec3(0.1, 0.2, 0.3), glm::dvec3(0.0, 0.0, -0.5), 0.01, 0.05};
  glm::dvec3 u = engine::evaluate(k, m, k.center).displacement;
  glm::dvec3 expected = engine::center_compliance(m, 0.01) * k.force;
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(u[i], expected[i], 1e-15);
}

TEST(Kelvinlet, WindowIsExactlyZeroAtAndBeyondTheSupport) {
  ElasticMaterial m;
  Kelvinlet k{glm::dvec3(0.0), glm::dvec3(1.0, 0.0, 0.0), 0.01, 0.05};
  EXPECT_EQ(engine::evaluate(k, m, glm::dvec3(0.05, 0.0, 0.0)).displacement, glm::dvec3(0.0));
  EXPECT_EQ(engine::evaluate(k, m, glm::dvec3(0.0, 0.2, 0.0)).displacement, glm::dvec3(0.0));
  // Just inside, the displacement and its slope both vanish continuously (w and w' are zero at R).
  glm::dvec3 near_edge = engine::evaluate(k, m, glm::dvec3(0.05 - 1e-6, 0.0, 0.0)).displacement;
  glm::dvec3 centre = engine::evaluate(k, m, glm::dvec3(0.0)).displacement;
  EXPECT_LT(glm::length(near_edge), 1e-8 * glm::length(centre));
}

}  // namespace
}  // namespace needle::test
