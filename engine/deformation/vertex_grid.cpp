#include "engine/deformation/vertex_grid.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>

namespace needle::engine {
namespace {

constexpr int kMaxCellsPerAxis = 256;  // bounds the table at 16 M cells for huge or flat meshes

}  // namespace

glm::ivec3 VertexGrid::cell_of(const glm::dvec3& p) const {
  glm::ivec3 c(glm::floor((p - origin_) / cell_size_));
  return glm::clamp(c, glm::ivec3(0), dims_ - 1);
}

VertexGrid VertexGrid::sort_vertices(Primitive& primitive, double cell_size) {
  if (!(cell_size > 0.0)) throw std::invalid_argument("VertexGrid: cell size must be positive");
  VertexGrid grid;
  const size_t n = primitive.vertices.size();
  if (n == 0) {
    grid.cell_start_ = {0, 0};
    return grid;
  }
  glm::dvec3 lo(primitive.vertices[0].position), hi = lo;
  for (const MeshVertex& v : primitive.vertices) {
    lo = glm::min(lo, glm::dvec3(v.position));
    hi = glm::max(hi, glm::dvec3(v.position));
  }
  const double extent = std::max({hi.x - lo.x, hi.y - lo.y, hi.z - lo.z});
  grid.cell_size_ = std::max(cell_size, extent / kMaxCellsPerAxis);
  grid.origin_ = lo;
  grid.dims_ = glm::max(glm::ivec3(glm::floor((hi - lo) / grid.cell_size_)) + 1, glm::ivec3(1));

  std::vector<size_t> cell(n);
  for (size_t i = 0; i < n; ++i) {
    glm::ivec3 c = grid.cell_of(glm::dvec3(primitive.vertices[i].position));
    cell[i] = grid.cell_index(c.x, c.y, c.z);
  }
  std::vector<uint32_t> order(n);
  std::iota(order.begin(), order.end(), 0u);
  std::stable_sort(order.begin(), order.end(), [&](uint32_t a, uint32_t b) { return cell[a] < cell[b]; });

  std::vector<uint32_t> new_index(n);
  std::vector<MeshVertex> sorted(n);
  const size_t cells = size_t(grid.dims_.x) * grid.dims_.y * grid.dims_.z;
  grid.cell_start_.assign(cells + 1, 0);
  for (size_t i = 0; i < n; ++i) {
    new_index[order[i]] = uint32_t(i);
    sorted[i] = primitive.vertices[order[i]];
    ++grid.cell_start_[cell[order[i]] + 1];
  }
  std::partial_sum(grid.cell_start_.begin(), grid.cell_start_.end(), grid.cell_start_.begin());
  for (uint32_t& index : primitive.indices) index = new_index[index];
  for (auto& level : primitive.coarser_indices)
    for (uint32_t& index : level) index = new_index[index];
  primitive.vertices = std::move(sorted);
  return grid;
}

std::vector<VertexRange> VertexGrid::ranges_near(const std::vector<Sphere>& spheres) const {
  std::vector<VertexRange> ranges;
  for (const Sphere& s : spheres) {
    glm::ivec3 lo = cell_of(s.center - s.radius), hi = cell_of(s.center + s.radius);
    for (int z = lo.z; z <= hi.z; ++z) {
      for (int y = lo.y; y <= hi.y; ++y) {
        // Distance in (y, z) from the centre to this row of cells; the slice of the sphere left
        // over bounds the row's x range.
        double dy =
            std::max({0.0, origin_.y + y * cell_size_ - s.center.y, s.center.y - (origin_.y + (y + 1) * cell_size_)});
        double dz =
            std::max({0.0, origin_.z + z * cell_size_ - s.center.z, s.center.z - (origin_.z + (z + 1) * cell_size_)});
        double left = s.radius * s.radius - dy * dy - dz * dz;
        if (left < 0.0) continue;
        double rx = std::sqrt(left);
        int x0 = cell_of({s.center.x - rx, 0, 0}).x, x1 = cell_of({s.center.x + rx, 0, 0}).x;
        uint32_t first = cell_start_[cell_index(x0, y, z)], end = cell_start_[cell_index(x1, y, z) + 1];
        if (end > first) ranges.push_back({first, end - first});
      }
    }
  }
  std::sort(ranges.begin(), ranges.end(), [](const VertexRange& a, const VertexRange& b) { return a.first < b.first; });
  std::vector<VertexRange> merged;
  for (const VertexRange& r : ranges) {
    if (!merged.empty() && r.first <= merged.back().first + merged.back().count) {
      uint32_t end = std::max(merged.back().first + merged.back().count, r.first + r.count);
      merged.back().count = end - merged.back().first;
    } else {
      merged.push_back(r);
    }
  }
  return merged;
}

}  // namespace needle::engine
