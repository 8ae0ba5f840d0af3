// What a picture must show, computed from the geometry rather than from another picture: the
// lighting model of shaders/mesh.frag in closed form (a flat surface's colour in sRGB counts),
// the ray through a pixel's centre, where it meets a plane, and pixels read as numbers. So the
// checks built on them hold on any Vulkan device, whatever its rasterizer does at the edges.
#pragma once

#include <algorithm>
#include <cmath>
#include <glm/glm.hpp>

#include "engine/extent.hpp"
#include "engine/model.hpp"
#include "engine/rgba_image.hpp"
#include "engine/scene.hpp"
#include "engine/screen_projection.hpp"

namespace needle::test {

// IEC 61966-2-1 sRGB encoding of a linear value, as an 8-bit count.
inline int srgb_count(double linear) {
  linear = std::clamp(linear, 0.0, 1.0);
  double encoded = linear <= 0.0031308 ? 12.92 * linear : 1.055 * std::pow(linear, 1.0 / 2.4) - 0.055;
  return int(std::lround(encoded * 255.0));
}

inline double srgb_decode(int count) {
  const double c = count / 255.0;
  return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
}

// mesh.frag's colour of a surface of base colour `base` (linear) with material `m` at `point`,
// unit normal `n` facing the camera, under `lights`: ambient + per light n·l (diffuse +
// normalized Blinn-Phong specular), as sRGB counts. Without the specular anti-aliasing, which
// adds nothing where the normal hardly turns within a pixel (a flat face, a large sphere).
inline glm::ivec3 lit_counts(const engine::Material& m, const glm::dvec3& base, const glm::dvec3& n,
                             const glm::dvec3& point, const engine::Camera& camera, const engine::Lights& lights) {
  const glm::dvec3 v = glm::normalize(glm::dvec3(camera.position) - point);
  const double metallic = std::clamp(double(m.metallic_factor), 0.0, 1.0);
  const double roughness = std::clamp(double(m.roughness_factor), 0.04, 1.0);
  const double shininess = 2.0 / std::pow(roughness, 4.0) - 2.0;
  const glm::dvec3 specular = glm::mix(glm::dvec3(0.04), base, metallic), diffuse = base * (1.0 - metallic);
  glm::dvec3 color = glm::dvec3(lights.ambient) * base;
  for (size_t i = 0; i < std::min<size_t>(lights.directional.size(), 4); ++i) {
    const engine::DirectionalLight& light = lights.directional[i];
    const glm::dvec3 l = -glm::normalize(glm::dvec3(light.direction));
    const double n_dot_l = glm::dot(n, l);
    if (n_dot_l <= 0.0) continue;
    const glm::dvec3 h = glm::normalize(l + v);
    const double spec = std::pow(std::max(glm::dot(n, h), 0.0), shininess) * (shininess + 8.0) / 25.1327;
    color += glm::dvec3(light.color) * double(light.intensity) * n_dot_l * (diffuse + specular * spec);
  }
  return {srgb_count(color.r), srgb_count(color.g), srgb_count(color.b)};
}

struct Ray {
  glm::dvec3 origin;
  glm::dvec3 direction;  // unit
};

// The ray from the camera through the centre of pixel (x, y) (origin at the top left).
inline Ray pixel_ray(const engine::Camera& camera, engine::Extent extent, double x, double y) {
  const glm::dmat4 inverse = glm::inverse(glm::dmat4(engine::view_projection(camera, extent)));
  const glm::dvec2 ndc{(x + 0.5) / extent.width * 2.0 - 1.0, 1.0 - (y + 0.5) / extent.height * 2.0};
  const glm::dvec4 near = inverse * glm::dvec4(ndc, 0.0, 1.0), far = inverse * glm::dvec4(ndc, 1.0, 1.0);
  const glm::dvec3 a = glm::dvec3(near) / near.w, b = glm::dvec3(far) / far.w;
  return {a, glm::normalize(b - a)};
}

// Where the ray meets the plane through `point` with normal `n`; the ray's origin when parallel.
inline glm::dvec3 on_plane(const Ray& ray, const glm::dvec3& point, const glm::dvec3& n) {
  const double d = glm::dot(ray.direction, n);
  if (std::abs(d) < 1e-12) return ray.origin;
  return ray.origin + (glm::dot(point - ray.origin, n) / d) * ray.direction;
}

inline glm::ivec3 rgb(const engine::RgbaImage& image, int x, int y) {
  const uint8_t* p = image.at(uint32_t(x), uint32_t(y));
  return {p[0], p[1], p[2]};
}

inline int max_channel_difference(const glm::ivec3& a, const glm::ivec3& b) {
  const glm::ivec3 d = glm::abs(a - b);
  return std::max({d.x, d.y, d.z});
}

// Rec. 709 luma of a pixel, counts.
inline double luma(const engine::RgbaImage& image, int x, int y) {
  const glm::ivec3 c = rgb(image, x, y);
  return 0.2126 * c.x + 0.7152 * c.y + 0.0722 * c.z;
}

// Luma interpolated bilinearly between pixel centres at (x, y) (pixel units, centres at integers).
inline double luma_at(const engine::RgbaImage& image, double x, double y) {
  const int x0 = int(std::floor(x)), y0 = int(std::floor(y));
  const double fx = x - x0, fy = y - y0;
  auto at = [&](int px, int py) {
    return luma(image, std::clamp(px, 0, int(image.width) - 1), std::clamp(py, 0, int(image.height) - 1));
  };
  return (1 - fy) * ((1 - fx) * at(x0, y0) + fx * at(x0 + 1, y0)) +
         fy * ((1 - fx) * at(x0, y0 + 1) + fx * at(x0 + 1, y0 + 1));
}

}  // namespace needle::test
