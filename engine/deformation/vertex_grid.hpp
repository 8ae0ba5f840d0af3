// A primitive's rest vertices sorted by the cell of a uniform grid they fall in, so that the
// vertices near a point are a few contiguous index ranges: the deformation pass visits only
// those, and a bigger mesh costs it nothing away from the needle.
#pragma once

#include <glm/glm.hpp>
#include <vector>

#include "engine/model.hpp"

namespace needle::engine {

struct VertexRange {
  uint32_t first = 0;
  uint32_t count = 0;
};

class VertexGrid {
 public:
  // Sorts the primitive's vertices by grid cell (stable, so the order inside a cell is kept)
  // and rewrites its indices to match. cell_size > 0, in the primitive's own units.
  static VertexGrid sort_vertices(Primitive& primitive, double cell_size);

  // The vertices of every cell that any sphere touches, as ascending, non-overlapping ranges.
  std::vector<VertexRange> ranges_near(const std::vector<Sphere>& spheres) const;
  uint32_t vertex_count() const { return cell_start_.empty() ? 0 : cell_start_.back(); }

 private:
  size_t cell_index(int x, int y, int z) const { return (size_t(z) * dims_.y + size_t(y)) * dims_.x + size_t(x); }
  glm::ivec3 cell_of(const glm::dvec3& p) const;

  glm::dvec3 origin_{0.0};
  double cell_size_ = 1.0;
  glm::ivec3 dims_{1};
  std::vector<uint32_t> cell_start_;  // cells + 1 entries: vertices of cell c are [start[c], start[c + 1])
};

}  // namespace needle::engine
