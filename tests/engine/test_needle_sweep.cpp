// The needle without streaks or gaps at any angle (docs/RENDERING.md, "Specular anti-aliasing"):
// 32 poses of the needle over and in the layered block, as the window draws them on a CPU device
// (1280x720, no MSAA, render scale 1 close up or 0.5 at the task's framing), half in free space,
// half inserted with the section cut through it. Each
// pixel of the shaft (inside its projected outline by a pixel, where the hub does not hide it) is
// compared with its eight neighbours inside the outline: one brighter than all of them, or
// darker than all of them, by more than 48 counts of luma is isolated (a highlight that lit only
// the pixel centres falling in it: a dotted streak; a piece of something else over the shaft: a
// gap). None is allowed; without the specular anti-aliasing 6 of the 32 poses have 1 to 70 each.
// Geometry, not goldens: the same on any device.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <vector>

#include "engine/gpu_scene.hpp"
#include "engine/render_target.hpp"
#include "picture_geometry.hpp"
#include "tests/support/test_paths.hpp"
#include "vulkan_fixture.hpp"

namespace needle::test {
namespace {

constexpr engine::Extent kWindow{1280, 720};
constexpr double kShaftRadius_m = 0.0008;  // asset-gen's needle: the shaft, and the hub from 80 to 95 mm
constexpr double kHubStart_m = 0.08, kHubEnd_m = 0.095;
constexpr double kLumaJump = 48.0;  // counts; with the anti-aliasing no pixel stands out by more than 40

// The shaft between `from` and `to` (world) on the screen: each pixel inside its outline by a
// pixel, and not behind the hub, against its eight neighbours inside the outline: isolated when
// it is brighter than all of them, or darker than all of them, by more than kLumaJump. A dotted
// streak is bright pixels between dark ones along the highlight; a gap, pixels of something else
// between the shaft's. `inside` counts the pixels judged.
int isolated_pixels(const engine::RgbaImage& image, const engine::Camera& camera, const glm::dvec3& from,
                    const glm::dvec3& to, const glm::dvec3& hub_from, const glm::dvec3& hub_to, size_t* inside) {
  const std::optional<glm::vec2> a = engine::project_to_screen(camera, kWindow, glm::vec3(from));
  const std::optional<glm::vec2> b = engine::project_to_screen(camera, kWindow, glm::vec3(to));
  if (!a || !b) return -1;
  // The shaft's radius on the screen at both ends: across the axis and across the view.
  auto radius_px = [&](const glm::dvec3& p, const glm::vec2& at) {
    const glm::dvec3 side = glm::normalize(glm::cross(to - from, p - glm::dvec3(camera.position)));
    return double(glm::length(*engine::project_to_screen(camera, kWindow, glm::vec3(p + kShaftRadius_m * side)) - at));
  };
  const double ra = radius_px(from, *a), rb = radius_px(to, *b);
  const glm::dvec2 pa(*a), pb(*b);
  const double length = glm::length(pb - pa);
  const glm::dvec2 u = (pb - pa) / length, w(-u.y, u.x);
  // How far inside the outline (pixels) the centre of pixel (x, y) lies; negative outside.
  auto depth_inside = [&](int x, int y) {
    const glm::dvec2 d = glm::dvec2(x + 0.5, y + 0.5) - pa;
    const double along = glm::dot(d, u);
    if (along < 0.0 || along > length) return -1.0;
    return ra + (rb - ra) * along / length - std::abs(glm::dot(d, w));
  };
  // Whether the ray passes the hub (3 mm radius, nearer the camera than the shaft it may hide)
  // within 3.5 mm: the nearest point of the hub's axis segment to the ray.
  auto behind_hub = [&](int x, int y) {
    const Ray ray = pixel_ray(camera, kWindow, x, y);
    const glm::dvec3 h = hub_to - hub_from;
    const glm::dvec3 r = hub_from - ray.origin;
    // Minimise |ray.origin + t d - hub_from - s h| over t, then s in [0, 1].
    const double hh = glm::dot(h, h), hd = glm::dot(h, ray.direction);
    const double denominator = hh - hd * hd;
    double s = denominator > 1e-12 ? (glm::dot(r, ray.direction) * hd - glm::dot(r, h)) / denominator : 0.0;
    s = std::clamp(s, 0.0, 1.0);
    const glm::dvec3 q = hub_from + s * h;
    return glm::length(glm::cross(q - ray.origin, ray.direction)) < 0.0035;
  };
  const int x0 = int(std::floor(std::min(pa.x, pb.x) - ra - rb)), x1 = int(std::ceil(std::max(pa.x, pb.x) + ra + rb));
  const int y0 = int(std::floor(std::min(pa.y, pb.y) - ra - rb)), y1 = int(std::ceil(std::max(pa.y, pb.y) + ra + rb));
  int isolated = 0;
  *inside = 0;
  for (int y = std::max(y0, 1); y <= std::min(y1, int(kWindow.height) - 2); ++y) {
    for (int x = std::max(x0, 1); x <= std::min(x1, int(kWindow.width) - 2); ++x) {
      if (depth_inside(x, y) < 1.0 || behind_hub(x, y)) continue;
      double lo = 1e9, hi = -1e9;
      int neighbours = 0;
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          if ((dx || dy) && depth_inside(x + dx, y + dy) >= 0.5 && !behind_hub(x + dx, y + dy)) {
            const double l = luma(image, x + dx, y + dy);
            lo = std::min(lo, l), hi = std::max(hi, l), ++neighbours;
          }
        }
      if (neighbours < 3) continue;
      ++*inside;
      const double l = luma(image, x, y);
      isolated += l - hi > kLumaJump || lo - l > kLumaJump;
    }
  }
  return isolated;
}

class NeedleSweep : public VulkanTest {};

TEST_F(NeedleSweep, NoIsolatedPixelAlongTheShaftInThirtyTwoPoses) {
  engine::HeadlessTarget target(device(), kWindow);
  engine::RendererSettings settings;
  settings.msaa_samples = 1;  // as the window on a CPU device
  engine::SceneRenderer renderer(device(), target, settings);
  engine::GpuScene scene(renderer, engine::load_scene(test::source_dir() / "assets/scenes/tissue_block_task.json"));
  int total = 0;
  size_t judged = 0;
  for (int i = 0; i < 32; ++i) {
    const bool inserted = i >= 16;
    // Around the vertical through the block's centre (0.33, 0, 0.07), tilted 15 to 75 degrees.
    const double azimuth = 2.0 * M_PI * (i % 16) / 16.0 + 0.1, tilt = glm::radians(15.0 + 60.0 * (i % 8) / 7.0);
    engine::NeedleLoad needle;
    needle.contact = inserted ? engine::NeedleContact::Inserted : engine::NeedleContact::Free;
    needle.axis = glm::dvec3(std::sin(tilt) * std::cos(azimuth), std::sin(tilt) * std::sin(azimuth), -std::cos(tilt));
    needle.surface_point = {0.33 + 0.01 * std::cos(3.0 * i), 0.01 * std::sin(3.0 * i), 0.07};
    needle.tip = needle.surface_point + (inserted ? 0.02 : -0.015) * needle.axis;
    engine::FrameParams params = scene.frame_params(&needle);
    // Even poses close up at render scale 1; odd ones at the task's framing at 0.5, the automatic
    // scale's lowest step, drawn at half the size and spread over the target.
    const bool close_up = i % 2 == 0;
    renderer.set_render_scale(target, close_up ? 1.0f : 0.5f);
    if (close_up)
      params.camera.position = params.camera.target + 0.6f * (params.camera.position - params.camera.target);
    if (inserted) params.section = engine::section_through_needle(params.camera, &needle);
    engine::RgbaImage image;
    ASSERT_TRUE(renderer.draw(target, params, &image));
    // The shaft from 5 mm behind the tip (past its cone) to 5 mm before the hub.
    size_t inside = 0;
    const int isolated =
        isolated_pixels(image, params.camera, needle.tip - 0.005 * needle.axis, needle.tip - 0.075 * needle.axis,
                        needle.tip - kHubStart_m * needle.axis, needle.tip - kHubEnd_m * needle.axis, &inside);
    ASSERT_GE(isolated, 0) << "pose " << i << ": the shaft is behind the camera";
    EXPECT_EQ(isolated, 0) << "pose " << i << (inserted ? " (in the cut" : " (free")
                           << (close_up ? ", close up): " : ", scale 0.5): ") << isolated << " of " << inside
                           << " pixels of the shaft stand out from those alike";
    total += isolated;
    judged += inside;
  }
  EXPECT_GT(judged, 20000u) << "too few pixels of the shaft to judge";
  EXPECT_EQ(total, 0);
}

}  // namespace
}  // namespace needle::test
