// The section view (docs/RENDERING.md, "Section view"): the tissue cut along the needle's plane,
// the cut filled with each layer's colour, the needle inside visible; and the translucent mode.
// Goldens with the usual tolerance (image_compare.hpp) and pixel checks at projected points, all
// under the validation layer.
#include <gtest/gtest.h>

#include <algorithm>

#include "deformation_fixture.hpp"
#include "engine/gpu_scene.hpp"
#include "engine/render_target.hpp"
#include "engine/screen_projection.hpp"
#include "image_compare.hpp"
#include "task_sections.hpp"
#include "tests/support/test_paths.hpp"
#include "vulkan_fixture.hpp"

namespace needle::test {
namespace {

constexpr engine::Extent kSize{320, 240};

class SectionView : public VulkanTest {};

glm::ivec3 pixel(const engine::RgbaImage& image, glm::vec2 at) {
  const size_t i = (size_t(at.y) * image.width + size_t(at.x)) * 4;
  return {image.pixels[i], image.pixels[i + 1], image.pixels[i + 2]};
}

// The darkest red channel within 2 pixels of `at`: the needle is dark grey, the tissue pink.
int darkest_red(const engine::RgbaImage& image, glm::vec2 at) {
  int dark = 255;
  for (int dy = -2; dy <= 2; ++dy)
    for (int dx = -2; dx <= 2; ++dx) dark = std::min(dark, pixel(image, at + glm::vec2(dx, dy)).x);
  return dark;
}

TEST_F(SectionView, TheNeedleInsideTheSphereShowsInTheCutAndThroughTheTranslucentTissue) {
  engine::HeadlessTarget target(device(), kSize);
  engine::SceneRenderer renderer(device(), target);
  engine::GpuScene scene(renderer, engine::load_scene(test::source_dir() / "assets/scenes/penetrable_sphere.json"));
  const engine::NeedleLoad needle = sphere_load(engine::NeedleContact::Inserted, {-1.0, 0.0, 0.35}, 0.03);
  std::map<std::string, engine::RgbaImage> images;
  for (const char* mode : {"none", "cut", "translucent", "screen_door"}) {
    engine::FrameParams params = scene.frame_params(&needle);
    if (std::string(mode) == "cut") params.section = engine::section_through_needle(params.camera, &needle);
    if (std::string(mode) == "translucent" || std::string(mode) == "screen_door")
      params.section = engine::section_through_needle(params.camera, &needle, engine::Section::Mode::Translucent);
    renderer.set_translucency(std::string(mode) == "screen_door" ? engine::Translucency::ScreenDoor
                                                                 : engine::Translucency::Blended);
    ASSERT_TRUE(renderer.draw(target, params, &images[mode]));
  }
  EXPECT_TRUE(matches_golden(images["cut"], "section_sphere_cut"));
  EXPECT_TRUE(matches_golden(images["translucent"], "section_sphere_translucent"));
  EXPECT_TRUE(matches_golden(images["screen_door"], "section_sphere_screen_door"));
  // 2 cm in, the shaft is inside the tissue: hidden in the plain view, seen in both section modes.
  const glm::vec3 inside = glm::vec3(needle.tip - 0.01 * needle.axis);
  const std::optional<glm::vec2> at = engine::project_to_screen(scene.scene().camera, kSize, inside);
  ASSERT_TRUE(at);
  EXPECT_GT(darkest_red(images["none"], *at), 150);
  EXPECT_LT(darkest_red(images["cut"], *at), 120);
  EXPECT_LT(darkest_red(images["translucent"], *at), 120);
  EXPECT_LT(darkest_red(images["screen_door"], *at), 120);
}

TEST_F(SectionView, TheCutShowsEachLayerOfTheBlockInItsColour) {
  engine::HeadlessTarget target(device(), kSize);
  engine::SceneRenderer renderer(device(), target);
  engine::GpuScene scene(renderer, engine::load_scene(test::source_dir() / "assets/scenes/tissue_block.json"));
  // Into the block (top at z = 0, 0.1 m square at the origin) at 30 degrees, 3 cm deep.
  engine::NeedleLoad needle;
  needle.contact = engine::NeedleContact::Inserted;
  needle.axis = {0.8660254, 0.0, -0.5};
  needle.surface_point = {-0.02, 0.0, 0.0};
  needle.tip = needle.surface_point + 0.03 * needle.axis;
  engine::FrameParams params = scene.frame_params(&needle);
  const engine::Section section = engine::section_through_needle(params.camera, &needle);
  params.section = section;
  engine::RgbaImage image;
  ASSERT_TRUE(renderer.draw(target, params, &image));
  EXPECT_TRUE(matches_golden(image, "section_block_cut"));
  // Points of the cut plane in the middle of each layer (skin 2 mm, fat 10, muscle 28, bone 10),
  // 3 cm left of the block's centre, away from the needle: four colours, each its layer's.
  std::vector<glm::ivec3> colours;
  for (float z : {-0.001f, -0.007f, -0.026f, -0.045f}) {
    const float x = -0.03f;
    const glm::vec3 n = section.normal, p0 = section.point;
    const float y = p0.y - (n.x * (x - p0.x) + n.z * (z - p0.z)) / n.y;  // on the plane
    const std::optional<glm::vec2> at = engine::project_to_screen(params.camera, kSize, {x, y, z});
    ASSERT_TRUE(at);
    colours.push_back(pixel(image, *at));
  }
  for (size_t a = 0; a < colours.size(); ++a)
    for (size_t b = a + 1; b < colours.size(); ++b) {
      const glm::ivec3 d = glm::abs(colours[a] - colours[b]);
      EXPECT_GT(std::max({d.x, d.y, d.z}), 20) << "layers " << a << " and " << b;
    }
  // Muscle is the red one (base colour 0.62, 0.14, 0.14; lit, in sRGB about 223, 118, 118).
  EXPECT_GT(colours[2].x, colours[2].y + 60);
}

// A plane fixed as a task fixes it (docs/TASKS.md, "Section"): the block's y = 0 plane, facing
// the camera, with the needle crossing it out of plane (entering 15 mm in front of it at 45°).
// Where the shaft crosses the plane it shows dark in the cut; the part in front of the plane,
// inside the cut-away tissue, shows too (tools are never cut), so the picture shows the needle
// against the cut layers as a trainee sees a needle crossing a fixed anatomical plane.
TEST_F(SectionView, AFixedPlaneCutsTheBlockWithTheNeedleCrossingIt) {
  engine::HeadlessTarget target(device(), kSize);
  engine::SceneRenderer renderer(device(), target);
  engine::GpuScene scene(renderer, engine::load_scene(test::source_dir() / "assets/scenes/tissue_block.json"));
  engine::NeedleLoad needle;
  needle.contact = engine::NeedleContact::Inserted;
  needle.surface_point = {0.0, -0.015, 0.0};
  needle.axis = {0.0, 0.70710678, -0.70710678};
  needle.tip = needle.surface_point + 0.03 * needle.axis;  // crosses y = 0 at 15 mm deep
  engine::FrameParams params = scene.frame_params(&needle);
  engine::Section section;
  section.point = glm::vec3(0.0f);
  section.normal = glm::vec3(0.0f, params.camera.position.y > params.camera.target.y ? 1.0f : -1.0f, 0.0f);
  params.section = section;
  engine::RgbaImage cut;
  ASSERT_TRUE(renderer.draw(target, params, &cut));
  EXPECT_TRUE(matches_golden(cut, "section_block_fixed_plane_needle_across"));
  // The plane's point where the shaft crosses it, and one 2 cm to its side in the muscle.
  const std::optional<glm::vec2> crossing = engine::project_to_screen(params.camera, kSize, {0.0f, 0.0f, -0.015f});
  const std::optional<glm::vec2> beside = engine::project_to_screen(params.camera, kSize, {0.02f, 0.0f, -0.025f});
  ASSERT_TRUE(crossing && beside);
  EXPECT_LT(darkest_red(cut, *crossing), 120);
  EXPECT_GT(pixel(cut, *beside).x, 150);  // muscle's red in the cut face, no needle there
}

// The section view of the two layered tasks' scenes (task_sections.hpp): goldens cut and, in
// plane, translucent; the needle dark in the cut where the plain view shows tissue, a layer 15 mm
// beside it.
class TaskSectionView : public VulkanTest, public ::testing::WithParamInterface<TaskSection> {};

TEST_P(TaskSectionView, TheNeedleShowsInTheCutOfTheTasksLayers) {
  const TaskSection& c = GetParam();
  engine::HeadlessTarget target(device(), kSize);
  engine::SceneRenderer renderer(device(), target);
  engine::GpuScene scene(renderer, engine::load_scene(test::source_dir() / "assets/scenes" / c.scene));
  const engine::NeedleLoad needle = task_needle(c);
  engine::FrameParams params = task_frame(scene, needle);
  engine::RgbaImage plain, cut;
  ASSERT_TRUE(renderer.draw(target, params, &plain));
  const engine::Section section = task_section(c, params.camera, needle);
  params.section = section;
  ASSERT_TRUE(renderer.draw(target, params, &cut));
  EXPECT_TRUE(matches_golden(cut, c.golden));
  if (c.in_plane) {  // and see-through, the needle inside the layers
    engine::FrameParams translucent = params;
    translucent.section->mode = engine::Section::Mode::Translucent;
    engine::RgbaImage image;
    ASSERT_TRUE(renderer.draw(target, translucent, &image));
    EXPECT_TRUE(
        matches_golden(image, std::string(c.golden).replace(std::string(c.golden).find("in_plane"), 8, "translucent")));
  }
  // In plane, 10 mm above the tip; out of plane, where the shaft crosses the plane: inside the
  // tissue, so hidden in the plain view and dark (the needle) in the cut.
  const glm::dvec3 shown =
      c.in_plane ? needle.tip - 0.01 * needle.axis : needle.surface_point + (-c.entry_y / needle.axis.y) * needle.axis;
  const std::optional<glm::vec2> at = engine::project_to_screen(params.camera, kSize, glm::vec3(shown));
  ASSERT_TRUE(at);
  EXPECT_GT(darkest_red(plain, *at), 120);
  EXPECT_LT(darkest_red(cut, *at), 100);
  // A point of the cut 15 mm beside the needle at the same depth shows a layer, not the needle.
  const glm::vec3 beside = glm::vec3(shown) + glm::vec3(0.015f, 0.0f, 0.0f);
  const glm::vec3 on_plane = beside - glm::dot(beside - section.point, section.normal) * section.normal;
  const std::optional<glm::vec2> there = engine::project_to_screen(params.camera, kSize, on_plane);
  ASSERT_TRUE(there);
  EXPECT_GT(darkest_red(cut, *there), 120);
}

INSTANTIATE_TEST_SUITE_P(Tasks, TaskSectionView, kTaskSections, task_section_name);

}  // namespace
}  // namespace needle::test
