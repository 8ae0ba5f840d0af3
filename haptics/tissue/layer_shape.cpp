#include "haptics/tissue/layer_shape.hpp"

#include <array>
#include <cmath>
#include <stdexcept>

namespace needle::haptics {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// The index of the coordinate axis `n` lies along, or -1.
int axis_of(const Eigen::Vector3d& n) {
  for (int k = 0; k < 3; ++k)
    if (std::abs(std::abs(n[k]) - 1.0) < 1e-12) return k;
  return -1;
}

// The half-space {x : n·(x − p) ≤ 0}: bounded on one side of one axis when n is along it.
Aabb half_space_bounds(const Eigen::Vector3d& p, const Eigen::Vector3d& n) {
  Aabb b;
  const int k = axis_of(n);
  if (k >= 0) (n[k] > 0.0 ? b.hi[k] : b.lo[k]) = p[k];
  return b;
}

Aabb primitive_bounds(const SurfacePrimitive& p) {
  switch (p.kind) {
    case SurfacePrimitive::Kind::Sphere:
      return {(p.a.array() - p.radius).matrix(), (p.a.array() + p.radius).matrix()};
    case SurfacePrimitive::Kind::Plane:
      return half_space_bounds(p.a, p.b);
    case SurfacePrimitive::Kind::Capsule:
      return {(p.a.cwiseMin(p.b).array() - p.radius).matrix(), (p.a.cwiseMax(p.b).array() + p.radius).matrix()};
  }
  return {};
}

// Does `a` reach beyond `b` on some axis (by more than `eps`)?
bool reaches_beyond(const Aabb& a, const Aabb& b, double eps) {
  return (a.lo.array() < b.lo.array() - eps).any() || (a.hi.array() > b.hi.array() + eps).any();
}

std::optional<LayerConflict::Kind> slab_conflict(const LayerShape::SlabPlanes& a, const LayerShape::SlabPlanes& b,
                                                 double eps) {
  const double c = a.normal.dot(b.normal);
  if (std::abs(c) < 1.0 - 1e-9) return LayerConflict::Kind::PartialOverlap;            // unbounded slabs that cross
  const double lo = c > 0 ? b.lo : -b.hi, hi = c > 0 ? b.hi : -b.lo;                   // b along a's normal
  if (std::min(a.hi, hi) - std::max(a.lo, lo) <= eps) return std::nullopt;             // apart or touching
  if (a.lo >= lo - eps && a.hi <= hi + eps) return LayerConflict::Kind::HiddenInside;  // also when equal
  if (lo >= a.lo - eps && hi <= a.hi + eps) return std::nullopt;                       // b inside a
  return LayerConflict::Kind::PartialOverlap;
}

// Samples the common bounding box of the two shapes (clipped to ±1 m) on a 32³ grid.
std::optional<LayerConflict::Kind> sampled_conflict(const LayerShape& a, const LayerShape& b, double eps) {
  constexpr int n = 32;
  const Aabb world{Eigen::Vector3d::Constant(-1.0), Eigen::Vector3d::Constant(1.0)};
  const Aabb box = a.bounds().intersected(b.bounds()).intersected(world);
  if (box.empty()) return std::nullopt;
  bool overlap = false;
  bool a_outside_b = reaches_beyond(a.bounds(), b.bounds(), eps);
  bool b_outside_a = reaches_beyond(b.bounds(), a.bounds(), eps);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      for (int k = 0; k < n; ++k) {
        const Eigen::Vector3d f = ((Eigen::Vector3d(i, j, k).array() + 0.5) / n).matrix();
        const Eigen::Vector3d x = box.lo + f.cwiseProduct(box.hi - box.lo);
        const double pa = a.phi(x), pb = b.phi(x);
        overlap |= pa < -eps && pb < -eps;
        a_outside_b |= pa < -eps && pb > eps;
        b_outside_a |= pb < -eps && pa > eps;
      }
  if (!overlap) return std::nullopt;
  if (!a_outside_b) return LayerConflict::Kind::HiddenInside;                              // also when equal
  return b_outside_a ? std::optional(LayerConflict::Kind::PartialOverlap) : std::nullopt;  // else b nested in a
}

}  // namespace

LayerShape LayerShape::of_surface(std::span<const SurfacePrimitive> primitives, ImplicitSurface::Combine combine) {
  if (primitives.empty()) throw std::invalid_argument("a layer shape needs at least one primitive");
  Aabb bounds = primitive_bounds(primitives[0]);
  for (const SurfacePrimitive& p : primitives.subspan(1))
    bounds = combine == ImplicitSurface::Combine::Union ? bounds.merged(primitive_bounds(p))
                                                        : bounds.intersected(primitive_bounds(p));
  return LayerShape(ImplicitSurface(primitives, combine), bounds, std::nullopt);
}

LayerShape LayerShape::slab(const Eigen::Vector3d& outer_point, const Eigen::Vector3d& outward_normal,
                            double thickness) {
  if (!(thickness > 0.0)) throw std::invalid_argument("slab thickness must be positive");
  if (!(outward_normal.norm() > 1e-12)) throw std::invalid_argument("slab normal must be nonzero");
  const Eigen::Vector3d n = outward_normal.normalized();
  const Eigen::Vector3d inner_point = outer_point - thickness * n;
  const std::array<SurfacePrimitive, 2> planes{SurfacePrimitive::plane(outer_point, n),
                                               SurfacePrimitive::plane(inner_point, -n)};
  const Aabb bounds = half_space_bounds(outer_point, n).intersected(half_space_bounds(inner_point, -n));
  return LayerShape(ImplicitSurface(planes, ImplicitSurface::Combine::Intersection), bounds,
                    SlabPlanes{n, n.dot(inner_point), n.dot(outer_point)});
}

LayerShape LayerShape::box(const Eigen::Vector3d& min, const Eigen::Vector3d& max) {
  if (!(min.array() < max.array()).all()) throw std::invalid_argument("box min must be below max on every axis");
  std::array<SurfacePrimitive, 6> faces;
  for (int k = 0; k < 3; ++k) {
    const Eigen::Vector3d e = Eigen::Vector3d::Unit(k);
    faces[size_t(2 * k)] = SurfacePrimitive::plane(max, e);
    faces[size_t(2 * k + 1)] = SurfacePrimitive::plane(min, -e);
  }
  return LayerShape(ImplicitSurface(faces, ImplicitSurface::Combine::Intersection), Aabb{min, max}, std::nullopt);
}

LayerShape LayerShape::grid(std::shared_ptr<const SdfGrid> grid, double offset_m) {
  if (!grid) throw std::invalid_argument("a grid shape needs a grid");
  if (!(offset_m >= 0.0 && offset_m < 1.0)) throw std::invalid_argument("a grid shape's offset must be in [0, 1) m");
  LayerShape shape(ImplicitSurface(), Aabb{grid->origin(), grid->upper()}, std::nullopt);
  shape.grid_ = std::move(grid);
  shape.grid_offset_ = offset_m;
  return shape;
}

const char* layer_conflict_text(LayerConflict::Kind kind) {
  switch (kind) {
    case LayerConflict::Kind::PartialOverlap:
      return "overlaps an earlier layer without lying inside it";
    case LayerConflict::Kind::HiddenInside:
      return "holds an earlier layer wholly inside it (list inner layers after outer ones)";
  }
  return "?";
}

std::optional<LayerConflict> find_layer_conflict(std::span<const LayerShape> shapes) {
  constexpr double eps = 1e-6;  // m: layers may touch
  for (int j = 1; j < int(shapes.size()); ++j)
    for (int i = 0; i < j; ++i) {
      const LayerShape& a = shapes[size_t(i)];
      const LayerShape& b = shapes[size_t(j)];
      const auto kind = a.slab_planes() && b.slab_planes() ? slab_conflict(*a.slab_planes(), *b.slab_planes(), eps)
                                                           : sampled_conflict(a, b, eps);
      if (kind) return LayerConflict{i, j, *kind};
    }
  return std::nullopt;
}

}  // namespace needle::haptics
