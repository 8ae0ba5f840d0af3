#include "haptics/anatomy/surface_mesh.hpp"

#include <algorithm>
#include <array>
#include <unordered_map>

namespace needle::haptics::anatomy {

SurfaceMesh extract_surface(const SdfGrid& grid, double offset_m, int stride, double inset_m) {
  stride = std::max(stride, 1);
  const std::array<int, 3>& n = grid.nodes();
  // The strided lattice, with one node of "outside" around it so that the region closes at the box.
  std::array<int, 3> m{};
  for (size_t a = 0; a < 3; ++a) m[a] = (n[a] - 1) / stride + 1;
  const double h = grid.spacing() * stride;
  const auto value = [&](int i, int j, int k) -> double {
    if (i < 0 || j < 0 || k < 0 || i >= m[0] || j >= m[1] || k >= m[2]) return 1e6 * h;  // outside: the wall on the box
    const double phi = grid.quantum() * grid.value(i * stride, j * stride, k * stride) + offset_m;
    if (inset_m <= 0.0) return phi;
    const int face = std::min({i, j, k, m[0] - 1 - i, m[1] - 1 - j, m[2] - 1 - k});  // nodes to the box's nearest face
    return std::max(phi, inset_m - face * h);
  };
  const auto node = [&](int i, int j, int k) { return Eigen::Vector3d(grid.origin() + h * Eigen::Vector3d(i, j, k)); };
  // Cells are indexed by their lowest corner, from −1 (the padding) to m − 1.
  const auto cell_key = [&](int i, int j, int k) {
    return (int64_t(k + 1) * (m[1] + 1) + (j + 1)) * (m[0] + 1) + (i + 1);
  };
  SurfaceMesh mesh;
  std::unordered_map<int64_t, uint32_t> vertex_of_cell;
  const auto vertex = [&](int i, int j, int k) -> uint32_t {
    const int64_t key = cell_key(i, j, k);
    if (const auto it = vertex_of_cell.find(key); it != vertex_of_cell.end()) return it->second;
    std::array<double, 8> v{};
    for (int c = 0; c < 8; ++c) v[size_t(c)] = value(i + (c & 1), j + ((c >> 1) & 1), k + ((c >> 2) & 1));
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    int crossings = 0;
    for (int c = 0; c < 8; ++c)
      for (int axis = 0; axis < 3; ++axis) {
        const int d = c | (1 << axis);
        if (d == c) continue;
        const double a = v[size_t(c)], b = v[size_t(d)];
        if ((a <= 0.0) == (b <= 0.0)) continue;
        const double t = a / (a - b);
        const Eigen::Vector3d pa = node(i + (c & 1), j + ((c >> 1) & 1), k + ((c >> 2) & 1));
        const Eigen::Vector3d pb = node(i + (d & 1), j + ((d >> 1) & 1), k + ((d >> 2) & 1));
        sum += pa + t * (pb - pa);
        ++crossings;
      }
    const Eigen::Vector3d p = sum / std::max(crossings, 1);
    const Eigen::Vector3d normal = grid.evaluate(p, offset_m).gradient;
    mesh.positions.push_back(p.cast<float>());
    mesh.normals.push_back(normal.cast<float>());
    const uint32_t index = uint32_t(mesh.positions.size() - 1);
    vertex_of_cell.emplace(key, index);
    return index;
  };
  // Every lattice edge from a node to its +axis neighbour that the surface crosses: the four cells
  // around it make a quad, wound so that it faces from the inside node to the outside one.
  for (int k = -1; k < m[2]; ++k)
    for (int j = -1; j < m[1]; ++j)
      for (int i = -1; i < m[0]; ++i) {
        const double a = value(i, j, k);
        for (int axis = 0; axis < 3; ++axis) {
          const std::array<int, 3> e{axis == 0, axis == 1, axis == 2};
          const double b = value(i + e[0], j + e[1], k + e[2]);
          if ((a <= 0.0) == (b <= 0.0)) continue;
          // The other two axes (u, w) in cyclic order, and the four cells sharing the edge.
          const int u = (axis + 1) % 3, w = (axis + 2) % 3;
          std::array<uint32_t, 4> q{};
          for (int c = 0; c < 4; ++c) {
            std::array<int, 3> cell{i, j, k};
            if (c == 1 || c == 2) cell[size_t(u)] -= 1;
            if (c == 2 || c == 3) cell[size_t(w)] -= 1;
            q[size_t(c)] = vertex(cell[0], cell[1], cell[2]);
          }
          // Going round the edge (u then w), the quad's normal is +axis: flip it when outward is −axis.
          const bool outward_plus = a <= 0.0;  // inside at the lower node: the surface faces +axis
          const std::array<uint32_t, 6> tris = outward_plus
                                                   ? std::array<uint32_t, 6>{q[0], q[1], q[2], q[0], q[2], q[3]}
                                                   : std::array<uint32_t, 6>{q[0], q[3], q[2], q[0], q[2], q[1]};
          mesh.indices.insert(mesh.indices.end(), tris.begin(), tris.end());
        }
      }
  return mesh;
}

}  // namespace needle::haptics::anatomy
