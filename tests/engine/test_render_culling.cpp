// What the renderer leaves out does not show: chunk culling gives the very same pixels as drawing
// every triangle, the tissue deformed or not, and a level of detail chosen by projected size
// stays within the golden tolerance of the full mesh at the size it was chosen for.
#include <gtest/gtest.h>

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

}  // namespace
}  // namespace needle::test
