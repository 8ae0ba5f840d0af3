// What the renderer leaves out does not show: chunk culling gives the very same pixels as drawing
// every triangle, the tissue deformed or not, and a level of detail chosen by projected size
// stays within the golden tolerance of the full mesh at the size it was chosen for.
#include <gtest/gtest.h>

#include <functional>

#include "asset-gen/assets.hpp"
#include "deformation_fixture.hpp"
#include "engine/gpu_scene.hpp"
#include "engine/offscreen.hpp"
#include "engine/render_target.hpp"
#include "image_compare.hpp"
#include "tests/support/test_paths.hpp"
#include "vulkan_fixture.hpp"

namespace needle::test {
namespace {

const std::filesystem::path kScene = test::source_dir() / "assets/scenes/penetrable_sphere.json";

// Needle loads around the sphere as the scene's camera sees it: facing it, on the outline,
// behind, touching and inserted.
std::vector<engine::NeedleLoad> loads_around(const engine::Camera& camera) {
  const glm::dvec3 to_camera = glm::normalize(glm::dvec3(camera.position) - kSphereCentre);
  const glm::dvec3 side = glm::normalize(glm::cross(to_camera, glm::dvec3(0.0, 0.0, 1.0)));
  std::vector<engine::NeedleLoad> loads{sphere_load(engine::NeedleContact::Free, to_camera, -0.03)};
  for (const glm::dvec3& dir : {to_camera, side, -side, -to_camera, glm::normalize(to_camera + 2.0 * side)}) {
    loads.push_back(sphere_load(engine::NeedleContact::Touching, dir, 0.008));
    loads.push_back(sphere_load(engine::NeedleContact::Inserted, dir, 0.03, glm::radians(40.0), 1.0, {0, 0, 1}));
  }
  return loads;
}

class RenderCulling : public VulkanTest {
 protected:
  // Each of the loads around the sphere drawn with chunk culling and with every triangle (MSAA
  // `msaa`; with the section cut through the needle when `cut`): the same pixels, and culled
  // fewer than `share` of the triangles.
  void expect_no_pixel_changed(int msaa, bool cut, double share) {
    const engine::Extent size{320, 240};
    engine::HeadlessTarget target(device(), size);
    engine::SceneRenderer culled(device(), target, {msaa, true, true});
    engine::SceneRenderer every(device(), target, {msaa, true, false});
    engine::GpuScene culled_scene(culled, engine::load_scene(kScene));
    engine::GpuScene every_scene(every, engine::load_scene(kScene));
    size_t load_index = 0;
    for (const engine::NeedleLoad& load : loads_around(culled_scene.scene().camera)) {
      engine::RgbaImage a, b;
      engine::FrameParams pa = culled_scene.frame_params(&load), pb = every_scene.frame_params(&load);
      if (cut) pa.section = pb.section = engine::section_through_needle(pa.camera, &load);
      ASSERT_TRUE(culled.draw(target, pa, &a));
      ASSERT_TRUE(every.draw(target, pb, &b));
      EXPECT_EQ(a.pixels, b.pixels) << "load " << load_index;
      EXPECT_LT(double(culled.triangles_drawn()), share * double(every.triangles_drawn())) << "load " << load_index;
      ++load_index;
    }
  }
};

TEST_F(RenderCulling, CulledChunksChangeNoPixelOfTheDeformingTissue) { expect_no_pixel_changed(4, false, 1.0); }

// The section view's cut leaves out the chunks wholly on its cut-away side: the same pixels as
// drawing every triangle, fewer triangles (55 to 76 % here), the needle inserted (the deformed
// chunks kept).
TEST_F(RenderCulling, TheCutsCulledChunksChangeNoPixel) { expect_no_pixel_changed(1, true, 0.8); }

TEST_F(RenderCulling, TissueLevelOfDetailIsWithinTheGoldenToleranceAt1280x720) {
  const engine::Extent size{1280, 720};
  const engine::Scene scene = engine::load_scene(kScene);
  const engine::TissueParams tissue = *scene.assets.at(0).deformation;
  const engine::Model sphere = engine::convert_gltf(asset_gen::make_sphere(400, 400, {2, 4}), "sphere_400");
  const engine::Scene view = engine::framing_view(sphere, size);
  engine::HeadlessTarget target(device(), size);
  for (int msaa : {1, 4}) {
    engine::SceneRenderer lod(device(), target, {msaa, true, true});
    engine::SceneRenderer full(device(), target, {msaa, false, true});
    engine::GpuScene lod_scene(lod, sphere, view, tissue);
    engine::GpuScene full_scene(full, sphere, view, tissue);
    std::vector<engine::NeedleLoad> loads = loads_around(view.camera);
    loads.resize(4);  // at rest, and touching and inserted facing the camera
    engine::RgbaImage rest;
    for (size_t i = 0; i < loads.size(); ++i) {
      engine::RgbaImage a, b;
      ASSERT_TRUE(lod.draw(target, lod_scene.frame_params(&loads[i]), &a));
      ASSERT_TRUE(full.draw(target, full_scene.frame_params(&loads[i]), &b));
      // The coarser level was drawn: the 400 x 400 sphere fills most of the height.
      EXPECT_LT(lod.triangles_drawn(), full.triangles_drawn() / 2) << "load " << i;
      const size_t differing = differing_pixels(a, b);
      EXPECT_LE(double(differing), kMaxDifferingFraction * size.width * size.height)
          << "load " << i << ", MSAA " << int(msaa) << ": " << differing << " pixels differ";
      // The needle's dimple shows (500 to 3 300 pixels change here), so the comparison covers it.
      if (i == 0)
        rest = a;
      else
        EXPECT_GT(differing_pixels(a, rest), 400u) << "load " << i;
    }
  }
}

// The view leaves out the chunks wholly outside it: with the same eye a narrower field of view
// draws fewer triangles (the facing test alone depends on the eye only), and the same pixels as
// drawing every triangle.
TEST_F(RenderCulling, ChunksOutsideTheViewAreLeftOutAndChangeNoPixel) {
  const engine::Extent size{320, 240};
  engine::HeadlessTarget target(device(), size);
  engine::SceneRenderer culled(device(), target, {1, true, true});
  engine::SceneRenderer every(device(), target, {1, true, false});
  engine::GpuScene culled_scene(culled, engine::load_scene(kScene));
  engine::GpuScene every_scene(every, engine::load_scene(kScene));
  std::vector<size_t> drawn;
  for (const float fov : {45.0f, 8.0f}) {
    engine::FrameParams pa = culled_scene.frame_params(nullptr), pb = every_scene.frame_params(nullptr);
    pa.camera.fov_y_deg = pb.camera.fov_y_deg = fov;
    engine::RgbaImage a, b;
    ASSERT_TRUE(culled.draw(target, pa, &a));
    ASSERT_TRUE(every.draw(target, pb, &b));
    EXPECT_EQ(a.pixels, b.pixels) << "field of view " << fov;
    drawn.push_back(culled.triangles_drawn());
  }
  EXPECT_LT(double(drawn[1]), 0.5 * double(drawn[0]));
}

// A smaller sphere held inside the tissue sphere (SceneAsset::inside): without a section view it
// cannot be seen, so it is not drawn and the picture is that of the scene without it; with the
// section's cut, or with the camera inside the outer sphere's box, it is drawn.
TEST_F(RenderCulling, AnAssetInsideAnotherIsDrawnOnlyWhereItCanBeSeen) {
  const engine::Extent size{320, 240};
  engine::HeadlessTarget target(device(), size);
  engine::SceneRenderer renderer(device(), target, {1, true, true});
  const engine::Scene outer_only = engine::load_scene(kScene);
  engine::Scene with_inner = outer_only;
  engine::SceneAsset inner = with_inner.assets.at(0);
  inner.name = "inner";
  inner.deformation.reset();
  inner.inside = "sphere";
  inner.scale = glm::vec3(0.5f);
  inner.translation = glm::vec3(0.5 * kSphereCentre);  // centred in the outer one
  with_inner.assets.push_back(inner);
  engine::GpuScene without(renderer, outer_only), with(renderer, with_inner);
  const auto draw = [&](engine::GpuScene& scene, const std::function<void(engine::FrameParams&)>& change) {
    engine::FrameParams params = scene.frame_params(nullptr);
    change(params);
    engine::RgbaImage image;
    EXPECT_TRUE(renderer.draw(target, params, &image));
    return std::pair{image, renderer.triangles_drawn()};
  };
  const auto as_is = [](engine::FrameParams&) {};
  const auto [alone, alone_drawn] = draw(without, as_is);
  const auto [hidden, hidden_drawn] = draw(with, as_is);
  EXPECT_EQ(hidden.pixels, alone.pixels);
  EXPECT_EQ(hidden_drawn, alone_drawn);
  // Drawn anyway (the culling off), it changes no pixel: it was hidden.
  renderer.set_cull_inside(false);
  const auto [drawn_anyway, drawn_anyway_count] = draw(with, as_is);
  EXPECT_EQ(drawn_anyway.pixels, alone.pixels);
  EXPECT_GT(drawn_anyway_count, alone_drawn);
  renderer.set_cull_inside(true);
  const auto cut = [](engine::FrameParams& p) { p.section = engine::section_through_needle(p.camera, nullptr); };
  EXPECT_GT(draw(with, cut).second, draw(without, cut).second);
  const auto inside_outer = [](engine::FrameParams& p) {
    p.camera.position = glm::vec3(kSphereCentre + glm::dvec3(0.0, -0.75 * kSphereRadius, 0.0));  // between the two
    p.camera.target = glm::vec3(kSphereCentre);
  };
  EXPECT_GT(draw(with, inside_outer).second, draw(without, inside_outer).second);
}

// The asset an asset lies inside must exist, be another and be opaque (else hiding would change
// the picture).
TEST_F(RenderCulling, AnAssetInsideAnUnknownItselfOrATranslucentOneIsRefused) {
  engine::HeadlessTarget target(device(), {64, 64});
  engine::SceneRenderer renderer(device(), target);
  engine::Scene scene = engine::load_scene(kScene);
  scene.assets[1].inside = "no such asset";
  EXPECT_THROW(engine::GpuScene(renderer, scene), std::out_of_range);
  scene.assets[1].inside = "needle";
  EXPECT_THROW(engine::GpuScene(renderer, scene), engine::AssetError);
  engine::Model glass = engine::convert_gltf(asset_gen::make_sphere(8, 8), "glass");
  glass.materials.push_back({});
  glass.materials.back().alpha_mode = engine::AlphaMode::Blend;
  glass.primitives[0].material = int(glass.materials.size() - 1);
  scene.assets[0].model = std::make_shared<const engine::Model>(glass);
  scene.assets[0].deformation.reset();
  scene.assets[1].inside = "sphere";
  EXPECT_THROW(engine::GpuScene(renderer, scene), engine::AssetError);
}

}  // namespace
}  // namespace needle::test
