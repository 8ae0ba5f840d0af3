// The loss-of-resistance syringe drawn on the needle's hub over the epidural's scene, headless,
// against goldens: before the loss (the saline plunger held in the flavum under 11 N: 62.1 kPa, 466
// mmHg, not moved) and after it (the plunger given way 9 mm, the barrel at 60.3 kPa, the closed forms
// of docs/TISSUE.md). The needle is placed by hand, vertical on the midline with its tip 45 mm deep,
// so the pictures depend on nothing but the drawing. Nothing names the tissue at the tip.
#include <gtest/gtest.h>

#include "app/needle_tracker.hpp"
#include "image_compare.hpp"
#include "tests/support/test_paths.hpp"
#include "ui/panel_picture.hpp"
#include "ui/syringe_gauge.hpp"
#include "vulkan_fixture.hpp"

namespace needle::test {
namespace {

class SyringeGauge : public VulkanTest {
 protected:
  engine::RgbaImage draw(const haptics::SyringeSnapshot& syringe) {
    const training::Task task = training::load_task(test::source_dir() / "assets/tasks/epidural.json");
    ui::PictureScene scene{engine::load_scene(task.scene), std::nullopt};
    haptics::ToolSnapshot state;
    const training::Vec3 tip{0.33, 0.0, 0.07 - 0.045};
    for (int i = 0; i < 3; ++i) state.needle_tip_m[i] = tip[i];
    // The needle along -z: +x turned a quarter turn about +y.
    state.needle_orientation[0] = std::sqrt(0.5);
    state.needle_orientation[2] = std::sqrt(0.5);
    state.syringe = syringe;
    scene.needle = app::NeedleTracker().update(state);
    const engine::Camera camera = scene.scene.camera;
    return ui::panel_picture(
        device(), {480, 320},
        [&] {
          ui::draw_syringe_gauge({syringe, 0.028, tip, {0.0, 0.0, -1.0}, camera});
        },
        &scene);
  }
};

TEST_F(SyringeGauge, BeforeTheLossThePlungerIsHeldAtThumbForceOverArea) {
  haptics::SyringeSnapshot held;
  held.fluid = 1;
  held.layer = 6;
  held.thumb_force_N = 11.0;
  held.pressure_Pa = 11.0 / 1.77e-4;
  EXPECT_TRUE(matches_golden(draw(held), "syringe_gauge_before_loss"));
}

TEST_F(SyringeGauge, AfterTheLossThePlungerHasGivenWay) {
  haptics::SyringeSnapshot given;
  given.fluid = 1;
  given.layer = 7;
  given.thumb_force_N = 11.0;
  given.pressure_Pa = 60.3e3;
  given.travel_m = 0.009;
  given.flow_m3_per_s = 9.0e-6;
  EXPECT_TRUE(matches_golden(draw(given), "syringe_gauge_after_loss"));
}

}  // namespace
}  // namespace needle::test
