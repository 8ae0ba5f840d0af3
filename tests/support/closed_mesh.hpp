// Checks of a triangle mesh as a solid: every edge shared by two triangles wound opposite ways
// (closed, no crack), and the volume it encloses (the divergence theorem).
#pragma once

#include <Eigen/Geometry>
#include <cstdint>
#include <map>
#include <vector>

namespace needle::test {

// Every edge in exactly two triangles, once each way: a closed, consistently wound surface.
inline bool closed(const std::vector<uint32_t>& indices) {
  std::map<std::pair<uint32_t, uint32_t>, int> edges;
  for (size_t t = 0; t + 2 < indices.size(); t += 3)
    for (size_t e = 0; e < 3; ++e) ++edges[{indices[t + e], indices[t + (e + 1) % 3]}];
  for (const auto& [edge, count] : edges)
    if (count != 1 || edges.count({edge.second, edge.first}) == 0) return false;
  return !edges.empty();
}

// Every edge run as many times one way as the other: no crack, no hole, consistently wound, where
// the surface may touch itself along an edge (four triangles there, as surface nets can give).
inline bool watertight(const std::vector<uint32_t>& indices) {
  std::map<std::pair<uint32_t, uint32_t>, int> edges;
  for (size_t t = 0; t + 2 < indices.size(); t += 3)
    for (size_t e = 0; e < 3; ++e) ++edges[{indices[t + e], indices[t + (e + 1) % 3]}];
  for (const auto& [edge, count] : edges) {
    const auto back = edges.find({edge.second, edge.first});
    if (back == edges.end() || back->second != count) return false;
  }
  return !edges.empty();
}

// The volume the triangles enclose, `position(i)` the vertex i as an Eigen::Vector3d: positive
// when they face out.
template <typename Position>
double enclosed_volume(const std::vector<uint32_t>& indices, const Position& position) {
  double v = 0.0;
  for (size_t t = 0; t + 2 < indices.size(); t += 3) {
    const Eigen::Vector3d a = position(indices[t]), b = position(indices[t + 1]), c = position(indices[t + 2]);
    v += a.dot(b.cross(c)) / 6.0;
  }
  return v;
}

}  // namespace needle::test
