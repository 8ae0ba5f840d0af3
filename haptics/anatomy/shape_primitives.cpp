#include "haptics/anatomy/shape_primitives.hpp"

#include <algorithm>
#include <cmath>

namespace needle::haptics::anatomy {
namespace {

// The exact distance of a box of half sizes `half` at the origin: |max(q, 0)| + min(max qᵢ, 0).
double box_distance(const Eigen::Vector3d& p, const Eigen::Vector3d& half) {
  const Eigen::Vector3d q = p.cwiseAbs() - half;
  return q.cwiseMax(0.0).norm() + std::min(q.maxCoeff(), 0.0);
}

double phi_of(const RoundedBox& b, const Eigen::Vector3d& x) {
  const Eigen::Vector3d local = b.axes.transpose() * (x - b.centre);
  return box_distance(local, b.half - Eigen::Vector3d::Constant(b.rounding)) - b.rounding;
}

double phi_of(const Capsule& c, const Eigen::Vector3d& x) {
  const Eigen::Vector3d ab = c.b - c.a;
  const double t = std::clamp((x - c.a).dot(ab) / std::max(ab.squaredNorm(), 1e-30), 0.0, 1.0);
  return (x - (c.a + t * ab)).norm() - c.radius;
}

double phi_of(const RoundedPrism& p, const Eigen::Vector3d& x) {
  const Eigen::Vector3d local = p.axes.transpose() * (x - p.centre);
  // The section's rounded rectangle, shrunk by the edge rounding; then extruded and rounded.
  const double r = p.corner;
  const double qx = std::abs(local.x()) - (p.half_x - p.edge - r), qz = std::abs(local.z()) - (p.half_z - p.edge - r);
  const double section = std::hypot(std::max(qx, 0.0), std::max(qz, 0.0)) + std::min(std::max(qx, qz), 0.0) - r;
  const double along = std::abs(local.y()) - (p.half_y - p.edge);
  return std::hypot(std::max(section, 0.0), std::max(along, 0.0)) + std::min(std::max(section, along), 0.0) - p.edge;
}

void bounds_of(const Eigen::Vector3d& centre, const Eigen::Matrix3d& axes, const Eigen::Vector3d& half,
               Eigen::Vector3d& lo, Eigen::Vector3d& hi) {
  const Eigen::Vector3d extent = axes.cwiseAbs() * half;
  lo = centre - extent;
  hi = centre + extent;
}

}  // namespace

double primitive_phi(const ShapePrimitive& p, const Eigen::Vector3d& x) {
  return std::visit([&](const auto& shape) { return phi_of(shape, x); }, p);
}

void primitive_bounds(const ShapePrimitive& p, Eigen::Vector3d& lo, Eigen::Vector3d& hi) {
  if (const auto* b = std::get_if<RoundedBox>(&p)) return bounds_of(b->centre, b->axes, b->half, lo, hi);
  if (const auto* c = std::get_if<Capsule>(&p)) {
    lo = c->a.cwiseMin(c->b).array() - c->radius;
    hi = c->a.cwiseMax(c->b).array() + c->radius;
    return;
  }
  const auto& r = std::get<RoundedPrism>(p);
  bounds_of(r.centre, r.axes, Eigen::Vector3d(r.half_x, r.half_y, r.half_z), lo, hi);
}

}  // namespace needle::haptics::anatomy
