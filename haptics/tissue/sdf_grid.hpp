// A signed distance sampled on a regular grid (φ < 0 inside, metres): nodes at origin + (i, j, k)·h,
// each stored as a whole number of quanta (int16), so a field of a few million nodes takes a few
// megabytes. Between nodes φ is trilinear and its gradient, normalised, is the normal; outside the
// grid's box φ is the nearest box point's φ plus the distance to the box (the grid's border nodes
// are outside the region, so the region is closed inside the box). Sampling allocates nothing and
// takes no lock: it runs in the servo tick. The error against the sampled function: docs/TISSUE.md
// ("Signed distance grids") and tests/haptics/test_sdf_grid.cpp.
#pragma once

#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

#include "haptics/constraints/implicit_surface.hpp"

namespace needle::haptics {

// What is wrong with a grid's description (its sizes, spacing, quantum or values).
struct SdfGridError : std::invalid_argument {
  using std::invalid_argument::invalid_argument;
};

class SdfGrid {
 public:
  // Design values bounding what a grid may be: a spacing of 0.1 mm to 10 mm (a needle's scale to a
  // coarse organ), at least 2 nodes an axis and at most 2^26 nodes (128 MiB), a quantum of 0.1 µm
  // to 1 mm; past them a grid is a typo or an attack, not anatomy.
  static constexpr double kMinSpacing_m = 1e-4, kMaxSpacing_m = 1e-2;
  static constexpr int64_t kMaxNodes = int64_t(1) << 26;
  static constexpr double kMinQuantum_m = 1e-7, kMaxQuantum_m = 1e-3;

  // Throws SdfGridError naming what is wrong: a coordinate of the origin not finite or beyond
  // ±10 m, a spacing or quantum outside its range, fewer than 2 nodes an axis, more than kMaxNodes,
  // or `values` not nodes[0]·nodes[1]·nodes[2] long (x fastest, then y, then z).
  SdfGrid(const Eigen::Vector3d& origin, double spacing_m, const std::array<int, 3>& nodes, double quantum_m,
          std::vector<int16_t> values);

  // (function, box, spacing, quantum) => the grid of the function's values at the nodes from
  // `lo` in steps of `spacing` up to at least `hi`, each rounded to the nearest quantum and
  // clamped to the int16 range (±32767 quanta: far from the surface φ saturates, still a lower
  // bound of the distance outside).
  static SdfGrid sample(const std::function<double(const Eigen::Vector3d&)>& phi, const Eigen::Vector3d& lo,
                        const Eigen::Vector3d& hi, double spacing_m, double quantum_m);
  // φ in quanta, rounded and clamped as sample() stores it.
  static int16_t quantise(double phi_m, double quantum_m);

  const Eigen::Vector3d& origin() const { return origin_; }
  double spacing() const { return spacing_; }
  const std::array<int, 3>& nodes() const { return nodes_; }
  double quantum() const { return quantum_; }
  Eigen::Vector3d upper() const {
    return origin_ + spacing_ * Eigen::Vector3d(nodes_[0] - 1, nodes_[1] - 1, nodes_[2] - 1);
  }
  const std::vector<int16_t>& values() const { return values_; }
  int16_t value(int i, int j, int k) const { return values_[index(i, j, k)]; }
  size_t bytes() const { return values_.size() * sizeof(int16_t); }

  // x => φ(x) + offset, the unit normal (the interpolant's gradient, normalised) and the
  // interpolant's second derivatives divided by its gradient's length (within a cell only the
  // mixed ones are nonzero).
  SurfaceSample evaluate(const Eigen::Vector3d& x, double offset_m = 0.0) const;
  // x => φ(x) + offset alone (no derivatives), what contains() and the overlap check need.
  double phi(const Eigen::Vector3d& x, double offset_m = 0.0) const;

 private:
  size_t index(int i, int j, int k) const {
    return (size_t(k) * size_t(nodes_[1]) + size_t(j)) * size_t(nodes_[0]) + size_t(i);
  }
  // The cell holding p (clamped into the box) and p's fractions in it.
  void locate(const Eigen::Vector3d& p, std::array<int, 3>& cell, Eigen::Vector3d& f) const;
  // The values at the corners of the cell holding `p` (in the box), in quanta, ordered v000, v100,
  // v010, v110, v001, v101, v011, v111 (a digit a cell step along x, y, z), and p's place `f` in it.
  std::array<double, 8> corners(const Eigen::Vector3d& p, Eigen::Vector3d& f) const;

  Eigen::Vector3d origin_;
  double spacing_;
  std::array<int, 3> nodes_;
  double quantum_;
  std::vector<int16_t> values_;
};

}  // namespace needle::haptics
