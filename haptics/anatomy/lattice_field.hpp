// A patient's fields while they are built: every structure sampled on one lattice (nodes at whole
// multiples of the spacing, one quantum), each over its own box of nodes. On one lattice the
// structures can be cut from each other node by node and stay exactly apart once interpolated:
// the trilinear interpolant of max(a, −b) is at least −(that of b), so where b's interpolant is
// inside (< 0) a's is outside; and a region cut to lie within another (max(a, c)) stays within it.
// So the layers' rules (disjoint, or a later one inside an earlier one; docs/TISSUE.md) hold on the
// grids by construction, not by luck of the sampling.
#pragma once

#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <span>
#include <vector>

#include "haptics/anatomy/shape_primitives.hpp"
#include "haptics/tissue/sdf_grid.hpp"

namespace needle::haptics::anatomy {

struct Lattice {
  double spacing_m = 1e-3;
  double quantum_m = 4e-6;
  // Where the shapes' own frame (the patient's) has its origin in the lattice's frame (the model's):
  // a shape is sampled at node − origin.
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();
  // The lattice node at or below / above a coordinate.
  int floor_index(double x) const;
  int ceil_index(double x) const;
  int16_t quanta(double phi_m) const { return SdfGrid::quantise(phi_m, quantum_m); }
};

class LatticeField {
 public:
  // The nodes covering [lo, hi] (the shapes' frame) and `margin` nodes beyond, every value
  // `fill_m` (outside).
  LatticeField(const Lattice& lattice, const Eigen::Vector3d& lo, const Eigen::Vector3d& hi, int margin, double fill_m);

  const Lattice& lattice() const { return lattice_; }
  const std::array<int, 3>& first() const { return first_; }
  const std::array<int, 3>& count() const { return count_; }
  Eigen::Vector3d position(int i, int j, int k) const;  // of the node at global indices, lattice frame
  Eigen::Vector3d shape_point(int i, int j, int k) const { return position(i, j, k) - lattice_.origin; }
  // The value at global node indices; `outside` where the field has no node.
  int16_t at(int i, int j, int k, int16_t outside) const;

  // Every node: the region beneath a height field, φ = (z − height(x, y)) / √(1 + |∇height|²) −
  // offset, the distance to the surface's tangent plane (exact for a plane, close for a gently curved
  // surface); `height` gives the height and writes the slopes. Shapes' frame.
  void assign_beneath(const std::function<double(double x, double y, double& dzdx, double& dzdy)>& height,
                      double offset_m);
  // Union: each node within `reach_m` of the primitive's box takes min(value, φ). With reach at
  // least the fill, a node's value stays a lower bound of its distance to the union.
  void add(const ShapePrimitive& p, double reach_m);
  void add(std::span<const ShapePrimitive> ps, double reach_m);
  // Cut away `other` (value = max(value, −other)), where other has nodes.
  void subtract(const LatticeField& other);
  // Keep only what lies within `other` moved `offset_quanta` inwards (value = max(value, other + offset)).
  void intersect(const LatticeField& other, int offset_quanta);
  // Whether any node is inside (value ≤ 0).
  bool empty() const;

  std::shared_ptr<const SdfGrid> grid() const;

 private:
  size_t index(int i, int j, int k) const {
    return (size_t(k - first_[2]) * size_t(count_[1]) + size_t(j - first_[1])) * size_t(count_[0]) +
           size_t(i - first_[0]);
  }
  template <class F>
  void for_nodes(const std::array<int, 3>& lo, const std::array<int, 3>& hi, F f);

  Lattice lattice_;
  std::array<int, 3> first_{}, count_{};
  std::vector<int16_t> values_;
};

}  // namespace needle::haptics::anatomy
