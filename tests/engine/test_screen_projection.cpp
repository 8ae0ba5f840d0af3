// Where a world point lands on the screen, against the pinhole camera in closed form: a camera at
// the origin looking along +y with z up and a 90 degree vertical field of view sees the point
// (x, d, z) at x / (d * aspect) and z / d in normalised device coordinates, y pointing up on the
// screen; pixels count from the top left.
#include <gtest/gtest.h>

#include "engine/screen_projection.hpp"

namespace needle::engine {
namespace {

Camera looking_along_y() {
  Camera c;
  c.position = {0.0f, 0.0f, 0.0f};
  c.target = {0.0f, 1.0f, 0.0f};
  c.up = {0.0f, 0.0f, 1.0f};
  c.fov_y_deg = 90.0f;
  c.near_m = 0.1f;
  c.far_m = 10.0f;
  return c;
}

TEST(ScreenProjection, PinholeCameraInClosedForm) {
  const engine::Extent extent{200, 100};  // aspect 2
  const Camera camera = looking_along_y();
  const auto centre = project_to_screen(camera, extent, {0.0f, 3.0f, 0.0f});
  ASSERT_TRUE(centre);
  EXPECT_NEAR(centre->x, 100.0f, 1e-3f);
  EXPECT_NEAR(centre->y, 50.0f, 1e-3f);
  // Up in the world is up on the screen: z / d = 0.5 -> y = (1 - 0.5) / 2 * 100.
  const auto above = project_to_screen(camera, extent, {0.0f, 2.0f, 1.0f});
  ASSERT_TRUE(above);
  EXPECT_NEAR(above->y, 25.0f, 1e-3f);
  // Right: x / (d * aspect) = 0.25 -> x = 1.25 / 2 * 200.
  const auto right = project_to_screen(camera, extent, {1.0f, 2.0f, 0.0f});
  ASSERT_TRUE(right);
  EXPECT_NEAR(right->x, 125.0f, 1e-3f);
  EXPECT_FALSE(project_to_screen(camera, extent, {0.0f, -1.0f, 0.0f})) << "behind the camera";
}

}  // namespace
}  // namespace needle::engine
