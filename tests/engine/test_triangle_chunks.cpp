// Chunk culling against the exact answer: every triangle it leaves out faces away from the eye
// (so back-face culling would have dropped it), and it does leave out most of the back half.
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include "asset-gen/assets.hpp"
#include "engine/gltf_loader.hpp"
#include "engine/passes/triangle_chunks.hpp"

namespace needle::engine {
namespace {

Primitive sphere(int n) { return convert_gltf(asset_gen::make_sphere(n, n), "sphere").primitives.at(0); }

// Which triangles (by first index) the ranges draw.
std::vector<bool> drawn(const Primitive& p, const std::vector<IndexRange>& ranges) {
  std::vector<bool> out(p.indices.size() / 3, false);
  for (const IndexRange& r : ranges)
    for (uint32_t i = r.first; i < r.first + r.count; i += 3) out[i / 3] = true;
  return out;
}

// n · (eye − a) of triangle t: its facing, in the transform's world.
double facing(const Primitive& p, size_t t, const glm::dvec3& eye, const glm::dmat4& model_to_world = glm::dmat4(1.0)) {
  glm::dvec3 v[3];
  for (int k = 0; k < 3; ++k)
    v[k] = glm::dvec3(model_to_world * glm::dvec4(glm::dvec3(p.vertices[p.indices[3 * t + k]].position), 1.0));
  return glm::dot(glm::cross(v[1] - v[0], v[2] - v[0]), eye - v[0]);
}

TEST(TriangleChunks, ChunksCoverEveryTriangleOnceInOrder) {
  const Primitive p = sphere(20);
  const auto chunks = build_triangle_chunks(p.vertices, p.indices, 64);
  uint32_t next = 0;
  for (const TriangleChunk& c : chunks) {
    EXPECT_EQ(c.first_index, next);
    EXPECT_LE(c.index_count, 3u * 64u);
    EXPECT_GE(c.cone_cos, std::cos(glm::radians(30.0f)));  // within 15° of the first normal: of each other within 30°
    next += c.index_count;
  }
  EXPECT_EQ(next, p.indices.size());
  EXPECT_THROW(build_triangle_chunks(p.vertices, p.indices, 0), std::invalid_argument);
}

TEST(TriangleChunks, LeavesOutOnlyTrianglesFacingAwayAndMostOfThem) {
  const Primitive p = sphere(100);  // centred at the origin in model space, radius 0.1
  const auto chunks = build_triangle_chunks(p.vertices, p.indices, 256);
  for (const glm::dvec3 eye : {glm::dvec3(0.0, -0.5, 0.15), glm::dvec3(0.3, 0.2, -0.1), glm::dvec3(0.0, 0.0, 0.12)}) {
    const std::vector<bool> kept = drawn(p, visible_ranges(chunks, glm::vec3(eye), {}));
    size_t away = 0, away_dropped = 0;
    for (size_t t = 0; t < kept.size(); ++t) {
      const double f = facing(p, t, eye);
      if (!kept[t])
        EXPECT_LT(f, 0.0) << "triangle " << t << " faces the eye at " << eye.x << "," << eye.y << "," << eye.z;
      if (f < 0) ++away, away_dropped += !kept[t];
    }
    // Cones of at most ~15° (plus the chunk's size seen from the eye, and the margin) cull what
    // has turned past ~110° from the eye: two thirds of the far side's area, more of its triangles.
    EXPECT_GT(double(away_dropped), 0.6 * double(away)) << eye.x << "," << eye.y << "," << eye.z;
  }
}

TEST(TriangleChunks, KeepsChunksWhereTheVerticesMayHaveMoved) {
  const Primitive p = sphere(100);
  const auto chunks = build_triangle_chunks(p.vertices, p.indices, 256);
  const glm::dvec3 eye(0.0, -0.5, 0.0);
  const Sphere moved{{0.0, 0.1, 0.0}, 0.02};  // on the far side
  const std::vector<bool> kept = drawn(p, visible_ranges(chunks, glm::vec3(eye), {moved}));
  const std::vector<bool> unmoved = drawn(p, visible_ranges(chunks, glm::vec3(eye), {}));
  size_t near_moved = 0, culled_when_unmoved = 0;
  for (size_t t = 0; t < kept.size(); ++t) {
    if (!unmoved[t]) EXPECT_LT(facing(p, t, eye), 0.0);
    const glm::dvec3 a(p.vertices[p.indices[3 * t]].position);
    if (glm::length(a - moved.center) < moved.radius) {
      ++near_moved;
      EXPECT_TRUE(kept[t]) << "triangle " << t << " has a vertex where the mesh may have moved";
      culled_when_unmoved += !unmoved[t];  // they face away: culled when nothing moved
    }
  }
  EXPECT_GT(near_moved, 50u);
  EXPECT_GT(culled_when_unmoved, near_moved / 2);
}

TEST(TriangleChunks, WorldTransformsScaleAndMirror) {
  const Primitive p = sphere(60);
  const auto chunks = build_triangle_chunks(p.vertices, p.indices, 256);
  const glm::dvec3 eye(0.5, -0.6, 0.3);
  // Placed, turned and stretched (positive determinant): the test in model space is still exact.
  glm::dmat4 m = glm::translate(glm::dmat4(1.0), glm::dvec3(0.4, 0.0, 0.1));
  m = glm::rotate(m, 0.7, glm::dvec3(0.0, 0.0, 1.0));
  m = glm::scale(m, glm::dvec3(1.0, 2.5, 0.5));
  const std::vector<bool> kept = drawn(p, visible_ranges(chunks, glm::mat4(m), glm::vec3(eye), {}));
  size_t dropped = 0;
  for (size_t t = 0; t < kept.size(); ++t) {
    if (kept[t]) continue;
    ++dropped;
    EXPECT_LT(facing(p, t, eye, m), 0.0) << "triangle " << t;
  }
  EXPECT_GT(dropped, kept.size() / 4);
  // A moved sphere given in world space reaches the chunks it covers after the transform.
  const glm::dvec3 back = glm::dvec3(m * glm::dvec4(0.0, 0.0, -0.1, 1.0));  // the south pole, facing away
  const std::vector<bool> with_moved = drawn(p, visible_ranges(chunks, glm::mat4(m), glm::vec3(eye), {{back, 0.01}}));
  EXPECT_TRUE(with_moved[0]);  // the first triangles are the south pole's fan
  EXPECT_FALSE(kept[0]);
  // Mirrored: the rasterizer's facing turns over, so nothing is left out.
  const glm::dmat4 mirror = glm::scale(glm::dmat4(1.0), glm::dvec3(-1.0, 1.0, 1.0));
  const auto all = visible_ranges(chunks, glm::mat4(mirror), glm::vec3(eye), {});
  ASSERT_EQ(all.size(), 1u);
  EXPECT_EQ(all[0].first, 0u);
  EXPECT_EQ(all[0].count, p.indices.size());
}

// The section's cut against the plane's closed form: a triangle left out has its three vertices
// beyond the plane (n · p + d > 0: the shader discards all of it); it leaves out most of those,
// whatever the chunks' facing (the back faces show through the cut); chunks where the mesh may
// have moved stay; through a placed, turned and stretched transform alike.
TEST(TriangleChunks, TheCutLeavesOutOnlyTrianglesWhollyBeyondItsPlaneAndMostOfThem) {
  const Primitive p = sphere(100);  // radius 0.1 about the origin in model space
  const auto chunks = build_triangle_chunks(p.vertices, p.indices, 256);
  glm::dmat4 m = glm::translate(glm::dmat4(1.0), glm::dvec3(0.4, 0.0, 0.1));
  m = glm::rotate(m, 0.7, glm::dvec3(0.0, 0.0, 1.0));
  m = glm::scale(m, glm::dvec3(1.0, 2.5, 0.5));
  for (const glm::dmat4& to_world : {glm::dmat4(1.0), m}) {
    const glm::dvec3 centre(to_world * glm::dvec4(0.0, 0.0, 0.0, 1.0));
    for (const glm::dvec3 dir : {glm::dvec3(0, -1, 0), glm::normalize(glm::dvec3(1, 1, 0.5)), glm::dvec3(0, 0, 1)}) {
      for (const double offset : {-0.05, 0.0, 0.04}) {
        const glm::dvec3 point = centre + offset * dir;
        const glm::vec4 plane(glm::vec3(dir), float(-glm::dot(dir, point)));
        const std::vector<bool> kept = drawn(p, ranges_kept_by_cut(chunks, glm::mat4(to_world), plane, {}));
        size_t beyond = 0, dropped = 0;
        for (size_t t = 0; t < kept.size(); ++t) {
          bool all_beyond = true;
          for (int k = 0; k < 3; ++k) {
            const glm::dvec3 v(to_world * glm::dvec4(glm::dvec3(p.vertices[p.indices[3 * t + k]].position), 1.0));
            all_beyond = all_beyond && glm::dot(dir, v - point) > 0.0;
          }
          beyond += all_beyond;
          dropped += !kept[t];
          if (!kept[t]) EXPECT_TRUE(all_beyond) << "triangle " << t << " left out but not wholly cut away";
        }
        // Chunks whose box crosses the plane stay: a band of them (runs along the sphere's
        // parallels, long near the poles); 74 to 94 % of the triangles beyond are left out here.
        EXPECT_GT(double(dropped), 0.7 * double(beyond)) << "offset " << offset;
        EXPECT_GT(beyond, kept.size() / 8) << "offset " << offset;
      }
    }
    // A moved sphere (world space) beyond the plane keeps its chunks: the deformed vertices may
    // have crossed it.
    const glm::dvec3 pole(to_world * glm::dvec4(0.0, 0.0, -0.1, 1.0));  // the south pole's fan, first
    const glm::vec4 plane(0.0f, 0.0f, -1.0f, float(glm::dot(glm::dvec3(0, 0, 1), centre)));  // cuts away z < centre
    EXPECT_FALSE(drawn(p, ranges_kept_by_cut(chunks, glm::mat4(to_world), plane, {}))[0]);
    EXPECT_TRUE(drawn(p, ranges_kept_by_cut(chunks, glm::mat4(to_world), plane, {{pole, 0.01}}))[0]);
  }
}

TEST(TriangleChunks, ChunksAreCutWhereTheNormalsTurn) {
  // Two triangles back to back: one chunk could not cull either side, so they go apart.
  std::vector<MeshVertex> v(3);
  v[0].position = {0, 0, 0}, v[1].position = {1, 0, 0}, v[2].position = {0, 1, 0};
  const auto chunks = build_triangle_chunks(v, {0, 1, 2, 0, 2, 1}, 256);
  ASSERT_EQ(chunks.size(), 2u);
  const glm::vec3 above(0.2f, 0.2f, 5.0f), below(0.2f, 0.2f, -5.0f);
  EXPECT_FALSE(chunk_faces_away(chunks[0], above));  // counter-clockwise seen from +z
  EXPECT_TRUE(chunk_faces_away(chunks[0], below));
  EXPECT_TRUE(chunk_faces_away(chunks[1], above));
  EXPECT_FALSE(chunk_faces_away(chunks[1], below));
  // Edge-on (in its plane) is kept: the rasterizer may round it either way.
  EXPECT_FALSE(chunk_faces_away(chunks[0], {3.0f, 3.0f, 0.0f}));
  EXPECT_FALSE(chunk_faces_away(chunks[1], {3.0f, 3.0f, 0.0f}));
}

}  // namespace
}  // namespace needle::engine
