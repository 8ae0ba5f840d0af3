// The mesh shader specialized per draw (engine/passes/scene_pass.cpp, shaders/mesh.frag: no
// discards for opaque unsectioned draws, no texture fetch for untextured materials) draws the same
// picture as the general shader it replaces: no pixel beyond the goldens' per-channel tolerance
// (image_compare.hpp), with the textured block and the deforming sphere, plain, cut and
// translucent, MSAA 1 and 4, under the validation layer.
#include <gtest/gtest.h>

#include <filesystem>

#include "deformation_fixture.hpp"
#include "engine/gpu_scene.hpp"
#include "engine/render_target.hpp"
#include "image_compare.hpp"
#include "tests/support/test_paths.hpp"
#include "vulkan_fixture.hpp"

namespace needle::test {
namespace {

class RenderPipelines : public VulkanTest {
 protected:
  // The scene drawn by one renderer with the specialized pipelines and with the general one, in
  // turn, for each section mode: the same pixels within the tolerance.
  void expect_same_picture(const std::filesystem::path& scene_file, const engine::NeedleLoad* load, int msaa) {
    engine::HeadlessTarget target(device(), {320, 240});
    engine::SceneRenderer renderer(device(), target, {msaa});
    engine::GpuScene scene(renderer, engine::load_scene(scene_file));
    for (const auto mode : {std::optional<engine::Section::Mode>{}, std::optional{engine::Section::Mode::Cut},
                            std::optional{engine::Section::Mode::Translucent}}) {
      engine::FrameParams params = scene.frame_params(load);
      if (mode) params.section = engine::section_through_needle(params.camera, load, *mode);
      engine::RgbaImage specialized, general;
      renderer.set_specialized_pipelines(true);
      ASSERT_TRUE(renderer.draw(target, params, &specialized));
      renderer.set_specialized_pipelines(false);
      ASSERT_TRUE(renderer.draw(target, params, &general));
      EXPECT_EQ(differing_pixels(specialized, general), 0u)
          << scene_file.filename() << " msaa " << msaa << " section " << (mode ? int(*mode) : -1);
    }
  }
};

TEST_F(RenderPipelines, SpecializedShadersDrawTheTexturedBlockAsTheGeneralOne) {
  for (int msaa : {1, 4}) expect_same_picture(test::source_dir() / "assets/scenes/tissue_block.json", nullptr, msaa);
}

TEST_F(RenderPipelines, SpecializedShadersDrawTheDeformingSphereAsTheGeneralOne) {
  const engine::Scene scene = engine::load_scene(test::source_dir() / "assets/scenes/penetrable_sphere.json");
  const glm::dvec3 to_camera = glm::normalize(glm::dvec3(scene.camera.position) - kSphereCentre);
  const engine::NeedleLoad inserted =
      sphere_load(engine::NeedleContact::Inserted, to_camera, 0.03, glm::radians(40.0), 1.0, {0, 0, 1});
  for (int msaa : {1, 4})
    expect_same_picture(test::source_dir() / "assets/scenes/penetrable_sphere.json", &inserted, msaa);
}

}  // namespace
}  // namespace needle::test
