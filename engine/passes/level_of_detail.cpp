#include "engine/passes/level_of_detail.hpp"

#include <cmath>
#include <limits>
#include <numbers>

namespace needle::engine {

double projected_radius_px(const Sphere& world, const Camera& camera, Extent extent) {
  const double distance = glm::length(world.center - glm::dvec3(camera.position));
  if (distance <= world.radius) return std::numeric_limits<double>::infinity();
  // The outline's angular radius is asin(r / d); the perspective maps tan(angle) to
  // (height / 2) / tan(fov / 2) pixels.
  const double angle = std::asin(world.radius / distance);
  const double half_fov = glm::radians(double(camera.fov_y_deg)) / 2.0;
  return std::tan(angle) / std::tan(half_fov) * extent.height / 2.0;
}

size_t choose_level(const std::vector<uint32_t>& triangles, double radius_px, double min_pixels) {
  const double disc = std::numbers::pi * radius_px * radius_px;
  for (size_t level = 0; level < triangles.size(); ++level) {
    if (disc / (triangles[level] / 2.0) >= min_pixels) return level;
  }
  return triangles.empty() ? 0 : triangles.size() - 1;
}

}  // namespace needle::engine
