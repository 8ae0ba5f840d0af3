// The region a tissue layer occupies, as a signed distance φ (metres, φ < 0 inside, unit
// gradient): any implicit surface of haptics/constraints (sphere, plane, capsule and their union
// or intersection), a slab between two parallel planes, or a box. Slab and box are intersections
// of half-spaces: φ is exact inside and on the surface and a lower bound of the distance outside,
// which is what contact detection and sphere tracing need. Or a signed distance grid (SdfGrid),
// shared between the shapes made of it, each with its offset: a generated anatomy's structure, or
// the layers beneath a surface at their depths (φ + d ≤ 0 is everything deeper than d). Each shape
// also carries its bounding box (infinite along the axes where it is unbounded) for the layers'
// overlap check.
#pragma once

#include <Eigen/Core>
#include <cmath>
#include <limits>
#include <memory>
#include <optional>
#include <span>

#include "haptics/constraints/implicit_surface.hpp"
#include "haptics/tissue/sdf_grid.hpp"

namespace needle::haptics {

// Axis-aligned box; ±infinity where unbounded. Empty when lo > hi on some axis.
struct Aabb {
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(-std::numeric_limits<double>::infinity());
  Eigen::Vector3d hi = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity());

  bool empty() const { return (lo.array() > hi.array()).any(); }
  // x within `margin` of the box (inside it or at most that far out on every axis).
  bool reaches(const Eigen::Vector3d& x, double margin) const {
    return (x.array() >= lo.array() - margin).all() && (x.array() <= hi.array() + margin).all();
  }
  Aabb intersected(const Aabb& o) const { return {lo.cwiseMax(o.lo), hi.cwiseMin(o.hi)}; }
  Aabb merged(const Aabb& o) const { return {lo.cwiseMin(o.lo), hi.cwiseMax(o.hi)}; }
};

// How far outside its surface a point still belongs to a layer (m). Layers are closed sets: a
// point on the face two layers share belongs to both, and the inner (later) one wins, so a tip
// that lands exactly on such a face, as it does whenever the faces lie on the tick grid, is never
// in "no layer". The tolerance closes the gaps double rounding leaves between faces meant to touch
// (about 1e-17 m at the scene's scale); a nanometre is 200 times below a tick's travel at the
// slowest advance the tissue model is meant for (0.2 mm/s at 1 kHz). Design value.
inline constexpr double kLayerSurfaceTolerance_m = 1e-9;

class LayerShape {
 public:
  // The existing surface form: primitives combined by union or intersection (φ < 0 inside).
  static LayerShape of_surface(std::span<const SurfacePrimitive> primitives, ImplicitSurface::Combine combine);
  // Between the plane through `outer_point` with unit `outward_normal` and the plane `thickness`
  // behind it (the side the needle enters from is the outer one).
  static LayerShape slab(const Eigen::Vector3d& outer_point, const Eigen::Vector3d& outward_normal, double thickness);
  // Axis-aligned, min < max on every axis.
  static LayerShape box(const Eigen::Vector3d& min, const Eigen::Vector3d& max);
  // The grid's region moved `offset_m` ≥ 0 inwards: {x : φ(x) + offset ≤ 0}.
  static LayerShape grid(std::shared_ptr<const SdfGrid> grid, double offset_m = 0.0);

  SurfaceSample evaluate(const Eigen::Vector3d& x) const {
    return grid_ ? grid_->evaluate(x, grid_offset_) : surface_.evaluate(x);
  }
  double phi(const Eigen::Vector3d& x) const { return grid_ ? grid_->phi(x, grid_offset_) : surface_.evaluate(x).phi; }
  // φ(x) ≤ kLayerSurfaceTolerance_m: inside or on the surface. A grid's region lies within its box,
  // so a point beyond the box by more than the tolerance is outside without sampling the grid.
  bool contains(const Eigen::Vector3d& x) const {
    if (grid_ && !bounds_.reaches(x, kLayerSurfaceTolerance_m)) return false;
    return phi(x) <= kLayerSurfaceTolerance_m;
  }
  const Aabb& bounds() const { return bounds_; }
  // The shape as primitives (slab and box: the intersection of their half-spaces); none for a grid.
  const ImplicitSurface& surface() const { return surface_; }
  // The grid and its offset, for a grid shape (else null and 0).
  const std::shared_ptr<const SdfGrid>& grid() const { return grid_; }
  double grid_offset() const { return grid_offset_; }
  // How much faster than the distance φ may change along a line: 1 for the exact and bounding
  // primitives, √3 for a grid (each of the trilinear interpolant's partial derivatives is a blend of
  // node differences of a distance, at most 1 each). A sphere tracer steps φ / this.
  double lipschitz() const { return grid_ ? std::sqrt(3.0) : 1.0; }

  struct SlabPlanes {  // the slab {x : lo ≤ n·x ≤ hi}
    Eigen::Vector3d normal;
    double lo, hi;
  };
  const std::optional<SlabPlanes>& slab_planes() const { return slab_; }

 private:
  LayerShape(ImplicitSurface surface, Aabb bounds, std::optional<SlabPlanes> slab)
      : surface_(surface), bounds_(bounds), slab_(slab) {}

  ImplicitSurface surface_;
  Aabb bounds_;
  std::optional<SlabPlanes> slab_;  // kept for the exact overlap test between slabs
  std::shared_ptr<const SdfGrid> grid_;
  double grid_offset_ = 0.0;
};

// Layers are listed outside in: a point belongs to the last layer whose shape holds it. Two
// layers must then either not overlap or the later must lie wholly inside the earlier (nested
// spheres); anything else is a conflict.
struct LayerConflict {
  enum class Kind {
    PartialOverlap,  // `later` overlaps `earlier` without lying inside it
    HiddenInside,    // `earlier` lies wholly inside `later`, so no point would ever belong to it
  };
  int earlier, later;
  Kind kind;
};
const char* layer_conflict_text(LayerConflict::Kind kind);

// The first conflicting pair in list order, if any. Exact for slabs (by their planes); otherwise
// decided on a 32³ grid over the two shapes' common bounding box (clipped to ±1 m where
// unbounded), ignoring points within 1 µm of either surface, so that layers may touch.
std::optional<LayerConflict> find_layer_conflict(std::span<const LayerShape> shapes);

}  // namespace needle::haptics
