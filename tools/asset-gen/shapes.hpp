// Triangle meshes of the generated assets, in the asset's own frame (metres, z up).
#pragma once

#include <cstdint>
#include <glm/glm.hpp>
#include <vector>

namespace needle::asset_gen {

// Triangle list with per-vertex normals and texture coordinates; CCW seen from outside.
struct MeshData {
  std::vector<glm::vec3> positions;
  std::vector<glm::vec3> normals;
  std::vector<glm::vec2> uvs;
  std::vector<uint32_t> indices;
  // Levels of detail: coarser triangle lists over the same vertices, finest first (written to
  // the glTF primitive's extras.needle_coarser_indices).
  std::vector<std::vector<uint32_t>> coarser_indices;
};

// Sphere of the thesis (section 3.3.2, eq. 3.29-3.31): x = r cos(a) cos(b), y = r cos(a) sin(b),
// z = r sin(a), parallels a = -90 + 180 i / p degrees (i = 0..p), meridians b = 360 j / m degrees
// (j = 0..m; j = m repeats j = 0 with u = 1 so the texture seam closes). Normals radial.
MeshData sphere_mesh(double radius, int parallels, int meridians);

// The sphere's triangles over every `step`-th parallel and meridian of sphere_mesh's vertices: a
// level of detail (parallels / step by meridians / step). std::invalid_argument unless step
// divides both and leaves a sphere (2 parallels, 3 meridians).
std::vector<uint32_t> sphere_indices(int parallels, int meridians, int step);

// A profile point of a surface of revolution about the x axis: (x, radius).
struct ProfilePoint {
  double x;
  double radius;
};

// Surface of revolution about +x through the profile points, one ring of `segments` quads per
// profile segment, each segment with its own (hard-edged) normals.
MeshData revolution_mesh(const std::vector<ProfilePoint>& profile, int segments);

// Axis-aligned box, each face a grid of quads no longer than `max_cell_m` (one quad when 0: what
// a rigid part needs; a deformable tissue needs vertices where it dimples), with the face's
// normal and UV 0..1 on each face.
MeshData box_mesh(const glm::vec3& min, const glm::vec3& max, float max_cell_m = 0.0f);

}  // namespace needle::asset_gen
