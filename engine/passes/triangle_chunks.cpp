#include "engine/passes/triangle_chunks.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace needle::engine {
namespace {

// How far past edge-on (in the cosine) a chunk must turn before it is left out: the rasterizer
// decides facing from rounded screen coordinates, so nearly edge-on triangles stay in.
constexpr float kFacingMargin = 0.01f;
// A chunk's normals stay within 15° of its first triangle's, so its cone is at most about that
// wide: the chunk is culled once it has turned past ~105° from the eye.
const float kMaxNormalSpreadCos = std::cos(glm::radians(15.0f));
// How far beyond the section's plane (m) a chunk must lie to be left out: the shader's single-
// precision positions round by far less at the scenes' metre scale.
constexpr double kCutMargin_m = 1e-5;

TriangleChunk make_chunk(const std::vector<MeshVertex>& vertices, const std::vector<uint32_t>& indices, uint32_t first,
                         uint32_t count) {
  TriangleChunk chunk{first, count};
  glm::vec3 lo(INFINITY), hi(-INFINITY), normal_sum(0.0f);
  std::vector<glm::vec3> normals;
  for (uint32_t i = first; i < first + count; i += 3) {
    const glm::vec3 a = vertices[indices[i]].position, b = vertices[indices[i + 1]].position,
                    c = vertices[indices[i + 2]].position;
    for (const glm::vec3& v : {a, b, c}) lo = glm::min(lo, v), hi = glm::max(hi, v);
    const glm::vec3 n = glm::cross(b - a, c - a);
    const float length = glm::length(n);
    if (length > 0.0f) normals.push_back(n / length);  // a degenerate triangle covers no pixel
  }
  chunk.center = (lo + hi) * 0.5f;
  chunk.half_extent = (hi - lo) * 0.5f;
  for (uint32_t i = first; i < first + count; ++i)
    chunk.radius = std::max(chunk.radius, glm::length(vertices[indices[i]].position - chunk.center));
  for (const glm::vec3& n : normals) normal_sum += n;
  const float sum_length = glm::length(normal_sum);
  if (normals.empty() || sum_length < 1e-6f * float(normals.size())) return chunk;  // no cone: never culled
  chunk.cone_axis = normal_sum / sum_length;
  float min_cos = 1.0f;
  for (const glm::vec3& n : normals) min_cos = std::min(min_cos, glm::dot(n, chunk.cone_axis));
  chunk.cone_cos = std::clamp(min_cos, -1.0f, 1.0f);
  chunk.cone_sin = std::sqrt(1.0f - chunk.cone_cos * chunk.cone_cos);
  return chunk;
}

}  // namespace

std::vector<TriangleChunk> build_triangle_chunks(const std::vector<MeshVertex>& vertices,
                                                 const std::vector<uint32_t>& indices, uint32_t triangles) {
  if (triangles == 0) throw std::invalid_argument("build_triangle_chunks: a chunk needs at least one triangle");
  auto unit_normal = [&](uint32_t i) {
    const glm::vec3 a = vertices[indices[i]].position;
    const glm::vec3 n = glm::cross(vertices[indices[i + 1]].position - a, vertices[indices[i + 2]].position - a);
    const float length = glm::length(n);
    return length > 0.0f ? n / length : glm::vec3(0.0f);
  };
  std::vector<TriangleChunk> chunks;
  const auto total = uint32_t(indices.size() / 3 * 3);
  for (uint32_t first = 0; first < total;) {
    // A chunk ends where a triangle turns too far from its first (a narrow cone culls more).
    const glm::vec3 seed = unit_normal(first);
    uint32_t end = first + 3;
    while (end < total && end - first < 3 * triangles) {
      const glm::vec3 n = unit_normal(end);
      if (n != glm::vec3(0.0f) && glm::dot(n, seed) < kMaxNormalSpreadCos) break;
      end += 3;
    }
    chunks.push_back(make_chunk(vertices, indices, first, end - first));
    first = end;
  }
  return chunks;
}

bool chunk_faces_away(const TriangleChunk& chunk, const glm::vec3& eye) {
  // A triangle with unit normal n through a point p faces away when n·(eye − p) < 0. With p in
  // the sphere (c, r): n·(eye − p) ≤ n·(eye − c) + r, and over the cone the largest n·(eye − c)
  // is L cos(θ − α), θ the angle from the axis to eye − c, α the half angle, L = |eye − c|.
  if (chunk.cone_cos <= 0.0f) return false;
  const glm::vec3 d = eye - chunk.center;
  const float distance = glm::length(d);
  if (distance <= chunk.radius) return false;
  const float cos_theta = glm::dot(d, chunk.cone_axis) / distance;
  const float sin_theta = std::sqrt(std::max(0.0f, 1.0f - cos_theta * cos_theta));
  const float cos_theta_minus_alpha = cos_theta * chunk.cone_cos + sin_theta * chunk.cone_sin;
  return cos_theta_minus_alpha < -chunk.radius / distance - kFacingMargin;
}

namespace {

bool touches(const glm::dvec3& center, double radius, const std::vector<Sphere>& spheres) {
  return std::any_of(spheres.begin(), spheres.end(),
                     [&](const Sphere& s) { return glm::length(center - s.center) < radius + s.radius; });
}

void append(std::vector<IndexRange>& ranges, const TriangleChunk& chunk) {
  if (!ranges.empty() && ranges.back().first + ranges.back().count == chunk.first_index)
    ranges.back().count += chunk.index_count;
  else
    ranges.push_back({chunk.first_index, chunk.index_count});
}

// A bound on the largest factor by which the linear part of `m` stretches a length: the square
// root of Gershgorin's bound on the largest eigenvalue of mᵀm (its largest absolute row sum);
// exact for a rotation times a scale.
double stretch_bound(const glm::dmat3& m) {
  const glm::dmat3 g = glm::transpose(m) * m;
  double largest = 0.0;
  for (int i = 0; i < 3; ++i) largest = std::max(largest, std::abs(g[0][i]) + std::abs(g[1][i]) + std::abs(g[2][i]));
  return std::sqrt(largest);
}

}  // namespace

std::vector<IndexRange> visible_ranges(const std::vector<TriangleChunk>& chunks, const glm::vec3& eye,
                                       const std::vector<Sphere>& moved) {
  std::vector<IndexRange> ranges;
  for (const TriangleChunk& chunk : chunks) {
    if (!touches(glm::dvec3(chunk.center), chunk.radius, moved) && chunk_faces_away(chunk, eye)) continue;
    append(ranges, chunk);
  }
  return ranges;
}

std::vector<IndexRange> ranges_kept_by_cut(const std::vector<TriangleChunk>& chunks, const glm::mat4& model_to_world,
                                           const glm::vec4& plane, const std::vector<Sphere>& moved) {
  const glm::dmat4 to_world(model_to_world);
  const double stretch = stretch_bound(glm::dmat3(to_world));
  const glm::dvec3 normal(plane);
  const glm::dvec3 normal_in_model = glm::transpose(glm::dmat3(to_world)) * normal;
  std::vector<IndexRange> ranges;
  for (const TriangleChunk& chunk : chunks) {
    const glm::dvec3 center(to_world * glm::dvec4(glm::dvec3(chunk.center), 1.0));
    // Wholly cut away: the box's nearest corner to the plane beyond it (n · M(c + e∘s) is least
    // at the signs s against Mᵀn), by a margin for the shader's rounding (10 µm).
    const double reach = glm::dot(glm::abs(normal_in_model), glm::dvec3(chunk.half_extent));
    const bool cut_away = glm::dot(normal, center) + double(plane.w) > reach + kCutMargin_m;
    if (cut_away && !touches(center, double(chunk.radius) * stretch, moved)) continue;
    append(ranges, chunk);
  }
  return ranges;
}

std::vector<IndexRange> visible_ranges(const std::vector<TriangleChunk>& chunks, const glm::mat4& model_to_world,
                                       const glm::vec3& eye, const std::vector<Sphere>& moved) {
  if (chunks.empty()) return {};
  if (glm::determinant(glm::mat3(model_to_world)) <= 0.0f) {
    const uint32_t first = chunks.front().first_index;
    return {{first, chunks.back().first_index + chunks.back().index_count - first}};
  }
  // Facing is kept by an affine map of positive determinant: test in model space. A sphere maps
  // into one whose radius grows by at most the inverse's Frobenius norm.
  const glm::dmat4 world_to_model = glm::inverse(glm::dmat4(model_to_world));
  const double stretch = stretch_bound(glm::dmat3(world_to_model));
  std::vector<Sphere> moved_model;
  for (const Sphere& s : moved)
    moved_model.push_back({glm::dvec3(world_to_model * glm::dvec4(s.center, 1.0)), s.radius * stretch});
  return visible_ranges(chunks, glm::vec3(world_to_model * glm::dvec4(glm::dvec3(eye), 1.0)), moved_model);
}

std::vector<IndexRange> index_ranges(const std::vector<TriangleChunk>& chunks) {
  std::vector<IndexRange> ranges;
  for (const TriangleChunk& chunk : chunks) append(ranges, chunk);
  return ranges;
}

ViewVolume view_volume(const glm::mat4& m) {
  const glm::vec4 x(m[0][0], m[1][0], m[2][0], m[3][0]), y(m[0][1], m[1][1], m[2][1], m[3][1]),
      z(m[0][2], m[1][2], m[2][2], m[3][2]), w(m[0][3], m[1][3], m[2][3], m[3][3]);
  ViewVolume v{{w + x, w - x, w + y, w - y, w + z, w - z}};
  for (glm::vec4& plane : v.planes) plane /= glm::length(glm::vec3(plane));
  return v;
}

std::vector<TriangleChunk> chunks_in_view(const std::vector<TriangleChunk>& chunks, const glm::mat4& model_to_world,
                                          const ViewVolume& view, const std::vector<Sphere>& moved) {
  const glm::dmat4 to_world(model_to_world);
  const double stretch = stretch_bound(glm::dmat3(to_world));
  std::vector<TriangleChunk> kept;
  kept.reserve(chunks.size());
  for (const TriangleChunk& chunk : chunks) {
    const glm::dvec3 center(to_world * glm::dvec4(glm::dvec3(chunk.center), 1.0));
    const double radius = double(chunk.radius) * stretch;
    const bool outside = std::any_of(view.planes.begin(), view.planes.end(), [&](const glm::vec4& p) {
      return glm::dot(glm::dvec3(p), center) + double(p.w) < -radius;
    });
    if (!outside || touches(center, radius, moved)) kept.push_back(chunk);
  }
  return kept;
}

}  // namespace needle::engine
