// Signed distance grids (haptics/tissue/sdf_grid.hpp): the sampling error against the analytic φ
// of a sphere and a box, the normal, the checks a grid's description gets, and a grid as a tissue
// layer: the layer rules and the needle's track work on it as on the analytic shapes.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <fstream>
#include <random>

#include "haptics/anatomy/sdf_file.hpp"
#include "haptics/tissue/kinematic_insertion.hpp"
#include "haptics/tissue/layer_shape.hpp"
#include "haptics/tissue/sdf_grid.hpp"
#include "haptics/tissue/tissue_model.hpp"
#include "scenario_files.hpp"

namespace needle::haptics {
namespace {

using Eigen::Vector3d;

constexpr double kSpacing = 1e-3;  // m
constexpr double kQuantum = 1e-6;  // m

double sphere_phi(const Vector3d& x) { return x.norm() - 0.02; }

// The exact Euclidean distance of a box of half sizes (15, 10, 8) mm centred at the origin.
double box_phi(const Vector3d& x) {
  const Vector3d q = x.cwiseAbs() - Vector3d(0.015, 0.010, 0.008);
  return q.cwiseMax(0.0).norm() + std::min(q.maxCoeff(), 0.0);
}

struct SamplingError {
  double max_m = 0.0;
  double normal_max_deg = 0.0;  // between the grid's normal and the analytic gradient, where it is smooth
};

// Over 200 000 random points within 3 mm of the surface (a needle meets the surface there).
template <class Phi>
SamplingError sampling_error(const SdfGrid& grid, Phi phi, bool smooth) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-0.024, 0.024);
  SamplingError e;
  for (int n = 0; n < 200000;) {
    const Vector3d x(u(rng), u(rng), u(rng));
    const double exact = phi(x);
    if (std::abs(exact) > 0.003) continue;
    ++n;
    const SurfaceSample s = grid.evaluate(x);
    e.max_m = std::max(e.max_m, std::abs(s.phi - exact));
    EXPECT_NEAR(grid.phi(x), s.phi, 1e-12);
    if (smooth) {
      const Vector3d g = x.normalized();
      e.normal_max_deg = std::max(e.normal_max_deg, std::acos(std::clamp(g.dot(s.gradient), -1.0, 1.0)) * 180.0 / M_PI);
    }
  }
  return e;
}

// A sphere of radius 20 mm on a 1 mm grid: the trilinear interpolant's error is h²/8 times the sum
// of φ's second derivatives along the axes (2/r across a sphere): 0.0125 h, plus half a quantum.
TEST(SdfGrid, ASphereAsAGridIsWithinTwoHundredthsOfTheSpacing) {
  const SdfGrid grid =
      SdfGrid::sample(sphere_phi, Vector3d::Constant(-0.03), Vector3d::Constant(0.03), kSpacing, kQuantum);
  const SamplingError e = sampling_error(grid, sphere_phi, true);
  EXPECT_LT(e.max_m, 0.02 * kSpacing);
  EXPECT_GT(e.max_m, 0.001 * kSpacing);  // the bound is not vacuous: the grid does differ
  EXPECT_LT(e.normal_max_deg, 3.0);
}

// A box's distance is linear over the middle of each face, where the trilinear cells are exact (to
// the quantum); it has kinks at the edges (outside) and on the diagonal planes (inside) that a cell
// cannot follow: there the error is a large fraction of the spacing, under 0.4 of it.
TEST(SdfGrid, ABoxAsAGridIsExactOnItsFacesAndWithinFourTenthsOfTheSpacingAtItsEdges) {
  const SdfGrid grid =
      SdfGrid::sample(box_phi, Vector3d::Constant(-0.03), Vector3d::Constant(0.03), kSpacing, kQuantum);
  const SamplingError e = sampling_error(grid, box_phi, false);
  EXPECT_LT(e.max_m, 0.4 * kSpacing);
  EXPECT_GT(e.max_m, 0.1 * kSpacing);
  double face = 0.0;  // within 1 mm of the top face, 3 mm from its edges
  for (double x = -0.012; x <= 0.012; x += 0.00037)
    for (double y = -0.007; y <= 0.007; y += 0.00041)
      for (double z = 0.0072; z <= 0.0088; z += 0.00013)
        face = std::max(face, std::abs(grid.phi(Vector3d(x, y, z)) - box_phi(Vector3d(x, y, z))));
  EXPECT_LE(face, 0.5 * kQuantum + 1e-12);
  // On a face's middle the normal is the face's.
  EXPECT_NEAR(grid.evaluate(Vector3d(0.0153, 0.0004, -0.0002)).gradient.x(), 1.0, 1e-9);
  EXPECT_NEAR(grid.evaluate(Vector3d(0.0003, 0.0, 0.0081)).gradient.z(), 1.0, 1e-9);
}

TEST(SdfGrid, OutsideItsBoxPhiGrowsWithTheDistanceToTheBox) {
  const SdfGrid grid =
      SdfGrid::sample(sphere_phi, Vector3d::Constant(-0.03), Vector3d::Constant(0.03), kSpacing, kQuantum);
  const Vector3d far(0.05, 0.0, 0.0);  // 20 mm beyond the box, 30 mm from the sphere
  EXPECT_NEAR(grid.phi(far), 0.03, 2e-6);
  EXPECT_NEAR(grid.evaluate(far).gradient.x(), 1.0, 1e-12);
  // A region that reaches the border (a ball larger than the box) ends at the box's faces.
  const SdfGrid cut = SdfGrid::sample([](const Vector3d& x) { return x.norm() - 0.05; }, Vector3d::Constant(-0.01),
                                      Vector3d::Constant(0.01), kSpacing, kQuantum);
  EXPECT_LT(cut.phi(Vector3d(0.0099, 0.0, 0.0)), 0.0);
  EXPECT_NEAR(cut.phi(Vector3d(0.0101, 0.0, 0.0)), 0.0001, 1e-12);
}

TEST(SdfGrid, AnOffsetMovesTheSurfaceInwards) {
  const SdfGrid grid =
      SdfGrid::sample(sphere_phi, Vector3d::Constant(-0.03), Vector3d::Constant(0.03), kSpacing, kQuantum);
  const Vector3d x(0.0, 0.0, 0.017);
  EXPECT_NEAR(grid.phi(x, 0.003), 0.0, 0.0002);
  const LayerShape inner = LayerShape::grid(std::make_shared<SdfGrid>(grid), 0.003);
  EXPECT_FALSE(inner.contains(Vector3d(0.0, 0.0, 0.0175)));
  EXPECT_TRUE(inner.contains(Vector3d(0.0, 0.0, 0.0165)));
}

TEST(SdfGrid, BadDescriptionsAreRefusedNamingWhatIsWrong) {
  const auto error = [](const Vector3d& origin, double spacing, std::array<int, 3> n, double quantum, size_t count,
                        int16_t fill) -> std::string {
    try {
      SdfGrid(origin, spacing, n, quantum, std::vector<int16_t>(count, fill));
    } catch (const SdfGridError& e) {
      return e.what();
    }
    return "no error";
  };
  EXPECT_EQ(error(Vector3d::Zero(), 1e-3, {2, 2, 2}, 1e-6, 8, 5), "no error");
  EXPECT_EQ(error(Vector3d::Zero(), 0.5, {2, 2, 2}, 1e-6, 8, 5), "spacing: must be in [0.0001, 0.01] m, got 0.5");
  EXPECT_EQ(error(Vector3d::Zero(), std::nan(""), {2, 2, 2}, 1e-6, 8, 5),
            "spacing: must be in [0.0001, 0.01] m, got nan");
  EXPECT_EQ(error(Vector3d(std::numeric_limits<double>::infinity(), 0, 0), 1e-3, {2, 2, 2}, 1e-6, 8, 5),
            "origin: each coordinate must be finite and within 10 m, got inf");
  EXPECT_EQ(error(Vector3d::Zero(), 1e-3, {2, 2, 2}, 0.0, 8, 5), "quantum: must be in [1e-07, 0.001] m, got 0");
  EXPECT_EQ(error(Vector3d::Zero(), 1e-3, {2, 1, 2}, 1e-6, 4, 5), "nodes: at least 2 along each axis, got 1");
  EXPECT_EQ(error(Vector3d::Zero(), 1e-3, {1 << 10, 1 << 10, 1 << 10}, 1e-6, 8, 5), "nodes: at most 67108864 in all");
  EXPECT_EQ(error(Vector3d::Zero(), 1e-3, {2, 2, 2}, 1e-6, 7, 5), "values: expected 8 (the nodes' product), got 7");
}

// Two grid layers, a box of "skin" and a box of "bone" inside it, on the same lattice: the layer
// rules (a later layer inside an earlier one), the track and the rigid stop work as for boxes.
TEST(SdfGrid, GridLayersFollowTheLayerRules) {
  const auto outer = std::make_shared<SdfGrid>(
      SdfGrid::sample(box_phi, Vector3d::Constant(-0.03), Vector3d::Constant(0.03), kSpacing, kQuantum));
  const auto bone_phi = [](const Vector3d& x) { return box_phi(2.0 * x) / 2.0; };  // half as large
  const auto inner = std::make_shared<SdfGrid>(
      SdfGrid::sample(bone_phi, Vector3d::Constant(-0.03), Vector3d::Constant(0.03), kSpacing, kQuantum));
  LayerMechanics skin;
  skin.stiffness_N_per_m = 200;
  skin.puncture_force_N = 1.0;
  LayerMechanics bone;
  bone.rigid = true;
  const TissueModel model({{"skin", LayerShape::grid(outer), skin}, {"bone", LayerShape::grid(inner), bone}});
  EXPECT_EQ(model.layer_at(Vector3d(0, 0, 0.007)), 0);
  EXPECT_EQ(model.layer_at(Vector3d(0, 0, 0.0)), 1);
  EXPECT_EQ(model.layer_at(Vector3d(0, 0, 0.009)), -1);
  // Swapped, the bone would hold the skin inside it: refused as for any shapes.
  EXPECT_THROW(TissueModel({{"bone", LayerShape::grid(inner), bone}, {"skin", LayerShape::grid(outer), skin}}),
               TissueLayerError);
  // Straight down from 2 mm above: the skin's surface at 8 mm, the bone's at 4 mm.
  const std::optional<InsertionStop> stop =
      first_rigid_surface(model, Vector3d(0.001, 0.0005, 0.010), -Vector3d::UnitZ(), 0.02);
  ASSERT_TRUE(stop.has_value());
  EXPECT_NEAR(stop->depth_m, 0.006, 0.05 * kSpacing);
  const std::vector<LayerBoundary> b =
      layer_boundaries(model, Vector3d(0.001, 0.0005, 0.010), -Vector3d::UnitZ(), 0.02);
  ASSERT_GE(b.size(), 2u);
  EXPECT_NEAR(b[0].depth_m, 0.002, 0.05 * kSpacing);
  EXPECT_EQ(b[0].layer, 0);
  EXPECT_NEAR(b[1].depth_m, 0.006, 0.05 * kSpacing);
  EXPECT_EQ(b[1].layer, 1);
}

// A grid written and read back is the same grid; a damaged file is one line saying what is wrong.
TEST(SdfFile, AGridRoundTripsAndADamagedFileIsRefused) {
  const SdfGrid grid =
      SdfGrid::sample(sphere_phi, Vector3d(-0.03, -0.025, -0.02), Vector3d(0.03, 0.025, 0.02), kSpacing, kQuantum);
  const std::string path = test::own_file("sphere.nsdf");
  anatomy::write_sdf_file(path, grid);
  const SdfGrid back = anatomy::read_sdf_file(path);
  EXPECT_EQ(back.values(), grid.values());
  EXPECT_EQ(back.nodes(), grid.nodes());
  EXPECT_EQ(back.origin(), grid.origin());
  EXPECT_EQ(back.spacing(), grid.spacing());
  const std::string bytes = anatomy::sdf_file_bytes(grid);
  const auto error = [&](const std::string& content) -> std::string {
    const std::string bad = test::own_file("bad.nsdf");
    std::ofstream(bad, std::ios::binary) << content;
    try {
      anatomy::read_sdf_file(bad);
    } catch (const anatomy::SdfFileError& e) {
      return std::string(e.what()).substr(bad.size() + 2);
    }
    return "no error";
  };
  EXPECT_EQ(error(bytes), "no error");
  EXPECT_EQ(error("NSDX" + bytes.substr(4)), "not a signed distance grid (no NSDF header)");
  EXPECT_EQ(error(bytes.substr(0, bytes.size() - 2)), std::to_string(bytes.size() - 2) +
                                                          " bytes, its node counts need " +
                                                          std::to_string(bytes.size()) + " (cut short)");
  EXPECT_EQ(error(bytes + "x"), std::to_string(bytes.size() + 1) + " bytes, its node counts need " +
                                    std::to_string(bytes.size()) + " (extra bytes)");
  std::string spacing = bytes;
  const double huge = 0.5;
  std::memcpy(spacing.data() + 4 + 4 + 12 + 24, &huge, 8);
  EXPECT_EQ(error(spacing), "spacing: must be in [0.0001, 0.01] m, got 0.5");
  std::string nan_origin = bytes;
  const double nan = std::nan("");
  std::memcpy(nan_origin.data() + 4 + 4 + 12, &nan, 8);
  EXPECT_EQ(error(nan_origin), "origin: each coordinate must be finite and within 10 m, got nan");
  std::string version = bytes;
  version[4] = 2;
  EXPECT_EQ(error(version), "NSDF version 2, this build reads 1");
  EXPECT_EQ(error(""), "not a signed distance grid (no NSDF header)");
}

}  // namespace
}  // namespace needle::haptics
