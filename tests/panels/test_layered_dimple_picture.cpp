// The layered target's scene with the skin tented before its puncture ("visual
// agreement"), against a golden: the snapshot a tented skin publishes (6 mm deflection, the skin's
// puncture depth in closed form, met at rest at the entry marker), through the layered needle
// tracker, into the scene's deformation pass. Drawn headless under the validation layer.
#include <gtest/gtest.h>

#include <cmath>

#include "app/needle_tracker.hpp"
#include "image_compare.hpp"
#include "tests/support/test_paths.hpp"
#include "ui/panel_picture.hpp"
#include "vulkan_fixture.hpp"

namespace needle::test {
namespace {

class LayeredDimplePicture : public VulkanTest {};

TEST_F(LayeredDimplePicture, TheTentedSkinBeforeItsPuncture) {
  constexpr double kSkinTop_m = 0.07, kDeflection_m = 0.006;
  haptics::ToolSnapshot s;
  s.needle_tip_m[0] = 0.33;
  s.needle_tip_m[2] = kSkinTop_m - kDeflection_m;
  s.needle_orientation[0] = std::sqrt(0.5);  // +x turned onto −z: straight down
  s.needle_orientation[2] = std::sqrt(0.5);
  s.tissue.surface_layer = 0;
  s.tissue.deflection_m = kDeflection_m;
  s.tissue.surface_point_m[0] = 0.33;
  s.tissue.surface_point_m[2] = kSkinTop_m;
  ui::PictureScene pressed{engine::load_scene(test::source_dir() / "assets/scenes/tissue_block_task.json"),
                           app::NeedleTracker(app::TissueKind::Layered).update(s)};
  ASSERT_EQ(pressed.needle->contact, engine::NeedleContact::Touching);
  // A closer camera over the entry, so that the dimple fills the picture.
  pressed.scene.camera.position = {0.36, -0.05, 0.105};
  pressed.scene.camera.target = {0.33, 0.0, 0.066};
  pressed.scene.camera.near_m = 0.01f;
  const engine::RgbaImage image = ui::panel_picture(
      device(), {480, 320}, [] {}, &pressed, 4);
  EXPECT_TRUE(matches_golden(image, "dimple_layered_target"));
  // The same needle over the undeformed block (the thesis's tracker sees no contact: no dimple)
  // is a different picture.
  ui::PictureScene rest = pressed;
  rest.needle = app::NeedleTracker().update(s);
  EXPECT_NE(ui::panel_picture(
                device(), {480, 320}, [] {}, &rest, 4)
                .pixels,
            image.pixels);
}

}  // namespace
}  // namespace needle::test
