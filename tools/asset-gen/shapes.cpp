#include "asset-gen/shapes.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

namespace needle::asset_gen {

MeshData sphere_mesh(double radius, int parallels, int meridians) {
  if (parallels < 2 || meridians < 3)
    throw std::invalid_argument("sphere: needs at least 2 parallels and 3 meridians, got " + std::to_string(parallels) +
                                " x " + std::to_string(meridians));
  const auto p = static_cast<uint32_t>(parallels);
  const auto m = static_cast<uint32_t>(meridians);
  MeshData mesh;
  const double pi = std::numbers::pi;
  for (uint32_t i = 0; i <= p; ++i) {
    const double alpha = -pi / 2 + pi * i / p;
    for (uint32_t j = 0; j <= m; ++j) {
      const double beta = 2 * pi * j / m;
      const glm::dvec3 n(std::cos(alpha) * std::cos(beta), std::cos(alpha) * std::sin(beta), std::sin(alpha));
      mesh.positions.emplace_back(radius * n);
      mesh.normals.emplace_back(n);
      mesh.uvs.emplace_back(double(j) / m, 1.0 - double(i) / p);  // north pole at the image's top
    }
  }
  mesh.indices = sphere_indices(parallels, meridians, 1);
  return mesh;
}

std::vector<uint32_t> sphere_indices(int parallels, int meridians, int step) {
  if (step < 1 || parallels % step != 0 || meridians % step != 0 || parallels / step < 2 || meridians / step < 3)
    throw std::invalid_argument("sphere: step " + std::to_string(step) + " does not divide " +
                                std::to_string(parallels) + " x " + std::to_string(meridians) + " into a sphere");
  const auto p = static_cast<uint32_t>(parallels), m = static_cast<uint32_t>(meridians),
             s = static_cast<uint32_t>(step);
  // Quad (i, j): a = (i, j), b = (i, j+s), c = (i+s, j+s), d = (i+s, j); (a, b, c) and (a, c, d)
  // turn counter-clockwise seen from outside. At the poles one of them is degenerate: skipped.
  auto at = [m](uint32_t i, uint32_t j) { return i * (m + 1) + j; };
  std::vector<uint32_t> indices;
  for (uint32_t i = 0; i < p; i += s)
    for (uint32_t j = 0; j < m; j += s) {
      const uint32_t a = at(i, j), b = at(i, j + s), c = at(i + s, j + s), d = at(i + s, j);
      if (i != 0) indices.insert(indices.end(), {a, b, c});
      if (i + s != p) indices.insert(indices.end(), {a, c, d});
    }
  return indices;
}

MeshData revolution_mesh(const std::vector<ProfilePoint>& profile, int segments) {
  MeshData mesh;
  const double pi = std::numbers::pi;
  const auto n = static_cast<uint32_t>(segments);
  for (size_t s = 0; s + 1 < profile.size(); ++s) {
    const ProfilePoint p0 = profile[s], p1 = profile[s + 1];
    // P(x, t) = (x, r cos t, r sin t); with the profile direction (dx, dr) the outward normal
    // is (dr, -dx cos t, -dx sin t) normalized, and (ds, dt) is counter-clockwise from outside.
    const double dx = p1.x - p0.x, dr = p1.radius - p0.radius, length = std::hypot(dx, dr);
    const auto base = static_cast<uint32_t>(mesh.positions.size());
    for (const ProfilePoint& p : {p0, p1})
      for (uint32_t k = 0; k <= n; ++k) {
        const double t = 2 * pi * k / n;
        mesh.positions.emplace_back(p.x, p.radius * std::cos(t), p.radius * std::sin(t));
        mesh.normals.emplace_back(dr / length, -dx / length * std::cos(t), -dx / length * std::sin(t));
        mesh.uvs.emplace_back(double(k) / n, double(s) / double(profile.size() - 1));
      }
    for (uint32_t k = 0; k < n; ++k) {
      const uint32_t a = base + k, d = base + k + 1, b = base + n + 1 + k, c = base + n + 2 + k;
      if (p1.radius > 0) mesh.indices.insert(mesh.indices.end(), {a, b, c});
      if (p0.radius > 0) mesh.indices.insert(mesh.indices.end(), {a, c, d});
    }
  }
  return mesh;
}

MeshData box_mesh(const glm::vec3& min, const glm::vec3& max, float max_cell_m) {
  const glm::vec3 center = (min + max) * 0.5f, half = (max - min) * 0.5f;
  const glm::vec3 X(1, 0, 0), Y(0, 1, 0), Z(0, 0, 1);
  // (u, v) per face with u x v = the face's outward normal.
  const glm::vec3 faces[6][2] = {{Y, Z}, {Z, Y}, {Z, X}, {X, Z}, {X, Y}, {Y, X}};
  // Quads along a face's edge of half-length h: enough that none is longer than max_cell_m.
  const auto cells = [&](const glm::vec3& axis) {
    const float length = 2.0f * glm::dot(half, axis);
    return max_cell_m > 0.0f ? std::max(1, int(std::ceil(length / max_cell_m - 1e-4f))) : 1;
  };
  MeshData mesh;
  for (const auto& [u, v] : faces) {
    const glm::vec3 normal = glm::cross(u, v);
    const auto base = static_cast<uint32_t>(mesh.positions.size());
    const int nu = cells(u), nv = cells(v);
    for (int j = 0; j <= nv; ++j)
      for (int i = 0; i <= nu; ++i) {
        const glm::vec2 c(-1.0f + 2.0f * float(i) / float(nu), -1.0f + 2.0f * float(j) / float(nv));
        mesh.positions.push_back(center + half * (normal + c.x * u + c.y * v));
        mesh.normals.push_back(normal);
        mesh.uvs.emplace_back((c.x + 1) / 2, (1 - c.y) / 2);
      }
    for (int j = 0; j < nv; ++j)
      for (int i = 0; i < nu; ++i) {
        const uint32_t a = base + uint32_t(j * (nu + 1) + i), b = a + 1, c = a + uint32_t(nu + 1) + 1, d = c - 1;
        mesh.indices.insert(mesh.indices.end(), {a, b, c, a, c, d});
      }
  }
  return mesh;
}

}  // namespace needle::asset_gen
