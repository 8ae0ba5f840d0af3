// The meshes drawn of a grid's region (haptics/anatomy/surface_mesh.hpp): closed, facing out,
// enclosing the region's volume, their vertices on its surface, and closed where the region is
// cut by the grid's box.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <map>

#include "haptics/anatomy/surface_mesh.hpp"
#include "tests/support/closed_mesh.hpp"

namespace needle::haptics::anatomy {
namespace {

using Eigen::Vector3d;

bool closed(const SurfaceMesh& m) { return test::closed(m.indices); }
double enclosed_volume(const SurfaceMesh& m) {
  return test::enclosed_volume(m.indices, [&](uint32_t i) { return Vector3d(m.positions[i].cast<double>()); });
}

TEST(SurfaceMesh, ASphereIsClosedFacesOutAndHoldsItsVolume) {
  const SdfGrid grid = SdfGrid::sample([](const Vector3d& x) { return x.norm() - 0.02; }, Vector3d::Constant(-0.03),
                                       Vector3d::Constant(0.03), 1e-3, 1e-6);
  for (const int stride : {1, 2}) {
    SCOPED_TRACE(stride);
    const SurfaceMesh m = extract_surface(grid, 0.0, stride);
    EXPECT_TRUE(closed(m));
    const double exact = 4.0 / 3.0 * M_PI * 0.02 * 0.02 * 0.02;
    EXPECT_NEAR(enclosed_volume(m) / exact, 1.0, 0.02 * stride);
    double off = 0.0, facing = 1.0;
    for (size_t i = 0; i < m.positions.size(); ++i) {
      const Vector3d p = m.positions[i].cast<double>();
      off = std::max(off, std::abs(p.norm() - 0.02));
      facing = std::min(facing, double(m.normals[i].cast<double>().dot(p.normalized())));
    }
    EXPECT_LT(off, 0.2e-3 * stride);  // within a fifth of the (strided) spacing
    EXPECT_GT(facing, 0.99);
  }
  // An offset shrinks it: 5 mm inwards, a 15 mm sphere.
  EXPECT_NEAR(enclosed_volume(extract_surface(grid, 0.005, 1)) / (4.0 / 3.0 * M_PI * 0.015 * 0.015 * 0.015), 1.0, 0.03);
}

TEST(SurfaceMesh, ARegionCutByTheBoxIsClosedAtTheBox) {
  // A half-space below z = 0 in a 20 mm box: a closed 20 x 20 x 10 mm block.
  const SdfGrid grid = SdfGrid::sample([](const Vector3d& x) { return x.z(); }, Vector3d::Constant(-0.01),
                                       Vector3d::Constant(0.01), 1e-3, 1e-6);
  const SurfaceMesh m = extract_surface(grid, 0.0, 1);
  EXPECT_TRUE(closed(m));
  EXPECT_NEAR(enclosed_volume(m), 0.02 * 0.02 * 0.01, 0.15 * 0.02 * 0.02 * 0.01);
}

}  // namespace
}  // namespace needle::haptics::anatomy
