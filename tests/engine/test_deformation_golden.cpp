// The penetrable sphere deforming around the needle, rendered frame after frame in one scene as
// the thesis's nonholonomic experiment goes: a dimple before puncture, the needle inserted,
// pivoted about its tip, then withdrawn; the last frame must be the sphere at rest again.
#include <gtest/gtest.h>

#include "deformation_fixture.hpp"
#include "engine/gpu_scene.hpp"
#include "engine/render_target.hpp"
#include "image_compare.hpp"
#include "tests/support/test_paths.hpp"
#include "vulkan_fixture.hpp"

namespace needle::test {
namespace {

constexpr engine::Extent kSize{320, 240};
const std::filesystem::path kScene = test::source_dir() / "assets/scenes/penetrable_sphere.json";
const glm::dvec3 kEntryDirection{-1.0, 0.0, 0.35};  // where the needle meets the sphere, from its centre

class DeformationGolden : public VulkanTest {};

TEST_F(DeformationGolden, DimpleInsertPivotWithdraw) {
  engine::HeadlessTarget target(device(), kSize);
  engine::SceneRenderer renderer(device(), target);
  engine::GpuScene scene(renderer, engine::load_scene(kScene));

  struct Step {
    const char* name;
    engine::NeedleLoad load;
  };
  engine::NeedleLoad away = sphere_load(engine::NeedleContact::Free, kEntryDirection, -0.03);
  std::vector<Step> steps = {
      {"rest", away},
      {"dimple", sphere_load(engine::NeedleContact::Touching, kEntryDirection, 0.008)},
      {"inserted", sphere_load(engine::NeedleContact::Inserted, kEntryDirection, 0.03)},
      // Pivoted upwards, in the picture's plane, pushing the tissue up.
      {"pivoted",
       sphere_load(engine::NeedleContact::Inserted, kEntryDirection, 0.03, glm::radians(45.0), 1.0, {0, 0, 1})},
      {"withdrawn", away},
  };
  std::map<std::string, engine::RgbaImage> images;
  for (const Step& step : steps) {
    engine::RgbaImage image;
    ASSERT_TRUE(renderer.draw(target, scene.frame_params(&step.load), &image));
    EXPECT_TRUE(matches_golden(image, std::string("deform_") + step.name)) << step.name;
    images[step.name] = std::move(image);
  }
  // Back to rest means the very same picture as before the needle came, not just a close one.
  EXPECT_EQ(images["withdrawn"].pixels, images["rest"].pixels);
  // And the loaded frames do differ from rest.
  EXPECT_NE(images["dimple"].pixels, images["rest"].pixels);
  EXPECT_NE(images["pivoted"].pixels, images["inserted"].pixels);
}

}  // namespace
}  // namespace needle::test
