// A triangle mesh of a grid's region (φ + offset ≤ 0), for drawing it: naive surface nets (one
// vertex per cell the surface crosses, at the mean of its edges' crossings, two triangles for each
// grid edge the surface crosses), closed where the region meets the grid's box (outside the box is
// outside), normals from the grid's own gradient. The one geometry everywhere: the mesh is the
// tissue model's region to within the grid's spacing times the stride.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "haptics/tissue/sdf_grid.hpp"

namespace needle::haptics::anatomy {

struct SurfaceMesh {
  std::vector<Eigen::Vector3f> positions;  // the grid's frame, m
  std::vector<Eigen::Vector3f> normals;    // unit, outward
  std::vector<uint32_t> indices;           // triangles, counter-clockwise seen from outside
};

// (grid, offset, stride ≥ 1: every stride-th node, inset ≥ 0) => the mesh; empty when the region is.
// With an inset the region is clipped `inset_m` inside the grid's box: the regions one grid gives at
// several offsets (the skin, the fat and the muscle beneath it) share the box's faces, and their
// meshes' walls there would lie on each other; inset by their rank they nest instead.
SurfaceMesh extract_surface(const SdfGrid& grid, double offset_m, int stride, double inset_m = 0.0);

}  // namespace needle::haptics::anatomy
