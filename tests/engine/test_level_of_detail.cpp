// Levels of detail: the choice by projected size against closed forms, the sphere's coarser
// index lists against its grid, and their way through glTF and the deformation's vertex sort.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "asset-gen/assets.hpp"
#include "asset-gen/shapes.hpp"
#include "engine/deformation/vertex_grid.hpp"
#include "engine/gltf_loader.hpp"
#include "engine/passes/level_of_detail.hpp"

namespace needle::engine {
namespace {

TEST(LevelOfDetail, ProjectedRadiusFollowsThePerspective) {
  Camera camera;
  camera.position = {0.0f, 0.0f, 0.0f};
  camera.fov_y_deg = 90.0f;  // tan(fov / 2) = 1: a tangent of t is t * height / 2 pixels
  // r / d = 3/5: the outline's half angle has tangent 3/4.
  EXPECT_NEAR(projected_radius_px({{0.0, 5.0, 0.0}, 3.0}, camera, {1280, 720}), 0.75 * 360.0, 1e-9);
  camera.fov_y_deg = 60.0f;  // tan 30° = 1/sqrt(3)
  EXPECT_NEAR(projected_radius_px({{0.0, 0.0, -5.0}, 3.0}, camera, {640, 480}), 0.75 * std::sqrt(3.0) * 240.0, 1e-4);
  EXPECT_TRUE(std::isinf(projected_radius_px({{0.0, 0.0, 0.5}, 1.0}, camera, {640, 480})));
}

TEST(LevelOfDetail, ChoosesTheFinestLevelWithAFewPixelsPerTriangle) {
  const std::vector<uint32_t> sphere_400{319200, 79600, 19800};  // 400, 200 and 100 parallels and meridians
  // A disc of radius 290 px: 264 208 px over the front half, 159 600 triangles (1.66 px each) at
  // full detail, 39 800 (6.6 px each) at the next level.
  EXPECT_EQ(choose_level(sphere_400, 290.0), 1u);
  EXPECT_EQ(choose_level(sphere_400, 290.0, 1.5), 0u);
  EXPECT_EQ(choose_level(sphere_400, 290.0, 10.0), 2u);
  // Exactly at the threshold counts: disc = 4 * 159 600 when r = sqrt(638 400 / pi).
  EXPECT_EQ(choose_level(sphere_400, std::sqrt(4.0 * 159600 / std::numbers::pi) * (1 + 1e-12)), 0u);
  EXPECT_EQ(choose_level(sphere_400, 1e9), 0u);
  EXPECT_EQ(choose_level(sphere_400, 1.0), 2u);  // none is coarse enough: the coarsest
  EXPECT_EQ(choose_level({5000}, 1.0), 0u);      // a mesh without levels
}

TEST(LevelOfDetail, SphereLevelsUseEveryStepthParallelAndMeridian) {
  for (auto [n, step] : {std::pair{400, 2}, {400, 4}, {12, 3}}) {
    const std::vector<uint32_t> coarse = asset_gen::sphere_indices(n, n, step);
    const uint32_t k = uint32_t(n / step);
    // The sphere of k x k: 2 k k triangles less the k degenerate ones at each pole.
    EXPECT_EQ(coarse.size(), 3u * (2 * k * k - 2 * k)) << n << " step " << step;
    for (uint32_t index : coarse) {
      const uint32_t i = index / uint32_t(n + 1), j = index % uint32_t(n + 1);
      ASSERT_EQ(i % step, 0u);
      ASSERT_EQ(j % step, 0u);
    }
  }
  EXPECT_EQ(asset_gen::sphere_indices(400, 400, 1), asset_gen::sphere_mesh(0.1, 400, 400).indices);
  EXPECT_THROW(asset_gen::sphere_indices(10, 10, 3), std::invalid_argument);  // 3 does not divide 10
  EXPECT_THROW(asset_gen::sphere_indices(8, 8, 8), std::invalid_argument);    // 1 x 1 is no sphere
}

TEST(LevelOfDetail, LevelsCrossGltfAndTheDeformationSort) {
  Model model = convert_gltf(asset_gen::make_sphere(40, 40, {2, 4}), "sphere");
  Primitive& p = model.primitives.at(0);
  ASSERT_EQ(p.coarser_indices.size(), 2u);
  EXPECT_EQ(p.coarser_indices[0], asset_gen::sphere_indices(40, 40, 2));
  EXPECT_EQ(p.coarser_indices[1], asset_gen::sphere_indices(40, 40, 4));
  EXPECT_TRUE(convert_gltf(asset_gen::make_sphere(40, 40), "sphere").primitives[0].coarser_indices.empty());

  // Sorting the vertices for the deformation pass renumbers the levels with the full mesh.
  std::vector<std::vector<glm::vec3>> before;
  for (const auto& level : p.coarser_indices) {
    before.emplace_back();
    for (uint32_t i : level) before.back().push_back(p.vertices[i].position);
  }
  VertexGrid::sort_vertices(p, 0.01);
  bool reordered = false;
  for (size_t l = 0; l < p.coarser_indices.size(); ++l) {
    for (size_t i = 0; i < p.coarser_indices[l].size(); ++i) {
      ASSERT_EQ(p.vertices[p.coarser_indices[l][i]].position, before[l][i]) << "level " << l << " index " << i;
      reordered = reordered || p.coarser_indices[l][i] != asset_gen::sphere_indices(40, 40, l == 0 ? 2 : 4)[i];
    }
  }
  EXPECT_TRUE(reordered);  // the sort did move vertices, so the check above means something
}

}  // namespace
}  // namespace needle::engine
