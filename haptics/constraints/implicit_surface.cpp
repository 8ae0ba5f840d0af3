#include "haptics/constraints/implicit_surface.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace needle::haptics {
namespace {

// Distance to a point c minus r: gradient (x − c)/d, Hessian (I − n nᵀ)/d.
SurfaceSample point_distance(const Eigen::Vector3d& x, const Eigen::Vector3d& c, double r) {
  SurfaceSample s;
  const Eigen::Vector3d d = x - c;
  const double len = d.norm();
  if (len < 1e-12) {  // at the centre any direction is a normal; φ = −r is still exact
    s.phi = -r;
    return s;
  }
  s.phi = len - r;
  s.gradient = d / len;
  s.hessian = (Eigen::Matrix3d::Identity() - s.gradient * s.gradient.transpose()) / len;
  return s;
}

}  // namespace

SurfacePrimitive SurfacePrimitive::sphere(const Eigen::Vector3d& centre, double radius) {
  if (!(radius > 0.0)) throw std::invalid_argument("sphere radius must be positive");
  return {Kind::Sphere, centre, Eigen::Vector3d::Zero(), radius};
}

SurfacePrimitive SurfacePrimitive::plane(const Eigen::Vector3d& point, const Eigen::Vector3d& outward_normal) {
  if (!(outward_normal.norm() > 1e-12)) throw std::invalid_argument("plane normal must be nonzero");
  return {Kind::Plane, point, outward_normal.normalized(), 0.0};
}

SurfacePrimitive SurfacePrimitive::capsule(const Eigen::Vector3d& end_a, const Eigen::Vector3d& end_b, double radius) {
  if (!(radius > 0.0)) throw std::invalid_argument("capsule radius must be positive");
  return {Kind::Capsule, end_a, end_b, radius};
}

SurfaceSample SurfacePrimitive::evaluate(const Eigen::Vector3d& x) const {
  switch (kind) {
    case Kind::Sphere:
      return point_distance(x, a, radius);
    case Kind::Plane: {
      SurfaceSample s;
      s.phi = b.dot(x - a);
      s.gradient = b;
      return s;
    }
    case Kind::Capsule: {
      const Eigen::Vector3d axis = b - a;
      const double len2 = axis.squaredNorm();
      const double t = len2 > 0.0 ? (x - a).dot(axis) / len2 : 0.0;
      if (t <= 0.0) return point_distance(x, a, radius);
      if (t >= 1.0) return point_distance(x, b, radius);
      // Cylinder part: distance to the axis line; the Hessian lives in the plane normal to the axis.
      const Eigen::Vector3d u = axis / std::sqrt(len2);
      const Eigen::Vector3d closest = a + t * axis;
      SurfaceSample s = point_distance(x, closest, radius);
      const double len = (x - closest).norm();
      if (len > 1e-12)
        s.hessian = (Eigen::Matrix3d::Identity() - u * u.transpose() - s.gradient * s.gradient.transpose()) / len;
      return s;
    }
  }
  return {};
}

ImplicitSurface::ImplicitSurface(std::span<const SurfacePrimitive> primitives, Combine combine) : combine_(combine) {
  if (primitives.size() > static_cast<size_t>(kMaxPrimitives))
    throw std::invalid_argument("too many surface primitives");
  for (const auto& p : primitives) primitives_[static_cast<size_t>(count_++)] = p;
}

SurfaceSample ImplicitSurface::evaluate(const Eigen::Vector3d& x) const {
  SurfaceSample best;
  best.phi =
      combine_ == Combine::Union ? std::numeric_limits<double>::infinity() : -std::numeric_limits<double>::infinity();
  for (int i = 0; i < count_; ++i) {
    const SurfaceSample s = primitives_[static_cast<size_t>(i)].evaluate(x);
    if (combine_ == Combine::Union ? s.phi < best.phi : s.phi > best.phi) best = s;
  }
  return best;
}

SurfaceMotion surface_motion(const SurfaceSample& s, const Eigen::Vector3d& velocity,
                             const Eigen::Vector3d& acceleration) {
  return {s.phi, s.gradient.dot(velocity), s.gradient.dot(acceleration) + velocity.dot(s.hessian * velocity)};
}

SurfaceContact classify_contact(double phi, double tolerance) {
  if (phi > tolerance) return SurfaceContact::Free;
  if (phi >= -tolerance) return SurfaceContact::OnSurface;
  return SurfaceContact::Penetrating;
}

}  // namespace needle::haptics
