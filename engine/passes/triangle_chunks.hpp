// A primitive's triangles cut into runs of consecutive triangles, each with a bounding sphere and
// a cone holding its face normals, so that a draw can leave out the runs that only face away from
// the camera. The runs follow the mesh's own index order (any mesh; meshes written row by row or
// patch by patch give long runs), and the test is conservative: what it leaves out, back-face
// culling would have discarded, so the picture does not change.
#pragma once

#include <array>
#include <glm/glm.hpp>
#include <vector>

#include "engine/model.hpp"

namespace needle::engine {

struct TriangleChunk {
  uint32_t first_index = 0;
  uint32_t index_count = 0;
  glm::vec3 center{0.0f};  // bounding sphere of the chunk's vertices, model space
  float radius = 0.0f;
  glm::vec3 half_extent{0.0f};  // of the vertices' axis-aligned box about `center`, model space
  glm::vec3 cone_axis{0.0f, 0.0f, 1.0f};
  float cone_sin = 1.0f;  // sine and cosine of the cone's half angle; a cone over 90° never culls
  float cone_cos = 0.0f;
};

struct IndexRange {
  uint32_t first = 0;
  uint32_t count = 0;
};

// Chunks of consecutive triangles of a triangle list over `vertices`: at most `triangles` (> 0)
// each, and cut where a triangle's normal turns more than 15° from the chunk's first.
std::vector<TriangleChunk> build_triangle_chunks(const std::vector<MeshVertex>& vertices,
                                                 const std::vector<uint32_t>& indices, uint32_t triangles);

// True when every triangle of the chunk faces away from a camera at `eye` (model space, through a
// transform with positive determinant), with a margin for the rasterizer's rounding.
bool chunk_faces_away(const TriangleChunk& chunk, const glm::vec3& eye);

// The index ranges to draw, in the mesh's order: the chunks that may face the eye or that touch a
// sphere where the vertices may have moved from the rest mesh the chunks were built from (model
// space), adjacent ones merged.
std::vector<IndexRange> visible_ranges(const std::vector<TriangleChunk>& chunks, const glm::vec3& eye,
                                       const std::vector<Sphere>& moved);

// The same for chunks drawn through `model_to_world`, with the eye and the moved spheres in world
// space. A mirroring transform turns the winding over: then no chunk is culled.
std::vector<IndexRange> visible_ranges(const std::vector<TriangleChunk>& chunks, const glm::mat4& model_to_world,
                                       const glm::vec3& eye, const std::vector<Sphere>& moved);

// The camera's view volume in world space: six planes (n, w), |n| = 1, with n · p + w ≥ 0 inside.
struct ViewVolume {
  std::array<glm::vec4, 6> planes{};
};
// The volume a view-projection matrix (clip = M p) draws: −w ≤ x, y ≤ w, and depth within −w ≤ z ≤ w,
// which holds a 0-to-w depth range too (the planes of Gribb and Hartmann, "Fast extraction of
// viewing frustum planes from the world-view-projection matrix", 2001).
ViewVolume view_volume(const glm::mat4& view_projection);

// The chunks (drawn through `model_to_world`) that may show in the view: those whose bounding
// sphere is not wholly beyond one of its planes, and those touching a `moved` sphere (world
// space), whose vertices may have left the rest mesh. In the mesh's order.
std::vector<TriangleChunk> chunks_in_view(const std::vector<TriangleChunk>& chunks, const glm::mat4& model_to_world,
                                          const ViewVolume& view, const std::vector<Sphere>& moved);

// The index ranges of every chunk, in the mesh's order, adjacent ones merged.
std::vector<IndexRange> index_ranges(const std::vector<TriangleChunk>& chunks);

// The index ranges to draw of a mesh cut by the section view (Cut): the fragments where
// plane.xyz · p + plane.w > 0 (world space, plane.xyz unit) are discarded and every face of the
// rest is drawn for the cap (section_caps.hpp), so no chunk is culled for its facing; the chunks lying wholly on that
// side (their box, through `model_to_world`) are left out, except those touching a
// `moved` sphere (world space), whose vertices may have left the rest mesh. Adjacent ones merged.
std::vector<IndexRange> ranges_kept_by_cut(const std::vector<TriangleChunk>& chunks, const glm::mat4& model_to_world,
                                           const glm::vec4& plane, const std::vector<Sphere>& moved);

}  // namespace needle::engine
