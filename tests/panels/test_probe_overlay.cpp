// The ultrasound probe drawn over the 3D view (ui/probe_overlay.hpp): the sphere_ultrasound task's
// probe over its scene, headless, against a golden, and the face's outline where the probe
// projects. Nothing but the drawing decides the picture (no needle, no session).
#include <gtest/gtest.h>

#include "app/echo_scene.hpp"
#include "engine/screen_projection.hpp"
#include "image_compare.hpp"
#include "tests/support/test_paths.hpp"
#include "ui/panel_picture.hpp"
#include "ui/probe_overlay.hpp"
#include "vulkan_fixture.hpp"

namespace needle::test {
namespace {

class ProbeOverlay : public VulkanTest {};

// The probe (0.4, 0, 0.1), beams down, 50 mm wide along x, 50 mm deep: its plane y = 0 faces the
// scene's camera (at y = −0.3), so the plane shows as a translucent rectangle down the sphere.
TEST_F(ProbeOverlay, TheFaceAndTheImagedPlaneAreDrawnWhereTheTasksProbeIs) {
  const training::Task task = training::load_task(test::source_dir() / "assets/tasks/sphere_ultrasound.json");
  ASSERT_TRUE(task.ultrasound_probe.has_value());
  const engine::UltrasoundProbe probe = app::to_engine(*task.ultrasound_probe);
  ui::PictureScene scene{engine::load_scene(task.scene), std::nullopt};
  const engine::Camera camera = scene.scene.camera;
  constexpr engine::Extent kSize{480, 320};
  const engine::RgbaImage with = ui::panel_picture(
      device(), kSize, [&] { ui::draw_probe(probe, camera); }, &scene);
  const engine::RgbaImage without = ui::panel_picture(
      device(), kSize, [] {}, &scene);
  EXPECT_TRUE(matches_golden(with, "probe_overlay_sphere_task"));
  const auto pixel = [](const engine::RgbaImage& image, glm::vec2 at, int dx, int dy) {
    return &image.pixels[(size_t(int(at.y) + dy) * image.width + size_t(int(at.x) + dx)) * 4];
  };
  // The face's near long edge (y = −5 mm), opaque cyan (120, 230, 255) within 2 pixels: bluer than the
  // pink tissue and than the plane's translucent fill over it.
  for (const float x : {0.385f, 0.4f, 0.415f}) {
    const auto at = engine::project_to_screen(camera, kSize, {x, -0.005f, 0.1f});
    ASSERT_TRUE(at);
    bool cyan = false;
    for (int dy = -2; dy <= 2; ++dy)
      for (int dx = -2; dx <= 2; ++dx) {
        const uint8_t* p = pixel(with, *at, dx, dy);
        cyan |= p[2] > 200 && p[2] > p[0] + 40;  // the tinted plane over pink: blue about red
      }
    EXPECT_TRUE(cyan) << "the probe's face at x = " << x;
  }
  // Inside the imaged plane (25 mm under the face), the tissue tinted bluer than without the probe.
  const auto inside = engine::project_to_screen(camera, kSize, {0.39f, 0.0f, 0.075f});
  ASSERT_TRUE(inside);
  const uint8_t *a = pixel(with, *inside, 0, 0), *b = pixel(without, *inside, 0, 0);
  EXPECT_GT(int(a[2]), int(b[2]) + 15);
  EXPECT_LT(int(a[0]), int(b[0]));
}

}  // namespace
}  // namespace needle::test
