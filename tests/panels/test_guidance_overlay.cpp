// A step's guidance drawn over the task's scene headless, against goldens: the penetrable task's
// insertion (planned axis and depth gauge with its band, the tip 28 mm deep) and the rigid task's
// touch (entry and target rings, the three normal markers along the normal nearest the tip). The
// tip and needle are placed by hand, so the pictures depend on nothing but the drawing. Also the
// layered tasks': the layered target's step to the target, the epidural's approach.
#include <gtest/gtest.h>

#include "app/needle_tracker.hpp"
#include "image_compare.hpp"
#include "tests/support/test_paths.hpp"
#include "ui/guidance_overlay.hpp"
#include "ui/panel_picture.hpp"
#include "vulkan_fixture.hpp"

namespace needle::test {
namespace {

namespace fs = std::filesystem;

class GuidanceOverlay : public VulkanTest {
 protected:
  engine::RgbaImage draw(const std::string& task_name, size_t step, const training::Vec3& tip,
                         const training::Vec3& axis, bool hide_layer_names = false) {
    training::Task task = training::load_task(test::source_dir() / "assets/tasks" / (task_name + ".json"));
    task.hide_layer_names = hide_layer_names;
    ui::PictureScene scene{engine::load_scene(task.scene), std::nullopt};
    haptics::ToolSnapshot state;
    for (int i = 0; i < 3; ++i) state.needle_tip_m[i] = tip[i];
    // The needle along `axis`: the rotation of +x onto it (a half-way quaternion).
    const double n = training::norm(axis);
    const training::Vec3 h{1.0 + axis[0] / n, axis[1] / n, axis[2] / n};
    const double hn = training::norm(h);
    state.needle_orientation[0] = h[0] / hn;
    state.needle_orientation[1] = 0.0;
    state.needle_orientation[2] = -h[2] / hn;
    state.needle_orientation[3] = h[1] / hn;
    scene.needle = app::NeedleTracker().update(state);
    const engine::Camera camera = scene.scene.camera;
    return ui::panel_picture(
        device(), {480, 320},
        [&] {
          ui::draw_guidance({&task, step, tip, camera});
        },
        &scene);
  }
};

TEST_F(GuidanceOverlay, InsertionShowsTheAxisAndTheDepthGauge) {
  // 28 mm along the insertion axis from the entry (0.32929, 0, 0.07071), direction (0.70711, 0, -0.70711).
  const training::Vec3 tip{0.32929 + 0.028 * 0.70711, 0.0, 0.07071 - 0.028 * 0.70711};
  EXPECT_TRUE(matches_golden(draw("penetrable_sphere", 1, tip, {0.70711, 0.0, -0.70711}), "guidance_insert"));
}

TEST_F(GuidanceOverlay, TouchShowsTheEntryTargetAndNormalMarkers) {
  const training::Task task = training::load_task(test::source_dir() / "assets/tasks/rigid_sphere.json");
  const training::Vec3 entry = task.markers[0].position;
  const training::Vec3 tip{entry[0] - 0.01, entry[1], entry[2] + 0.02};
  EXPECT_TRUE(matches_golden(draw("rigid_sphere", 0, tip, {0.0, 0.0, -1.0}), "guidance_touch"));
}

// The layered target's step to the target: the vertical planned axis, the target 35 mm
// deep and the depth gauge with its 31-38 mm band, the layers' starts marked on it (skin 0, fat 2,
// muscle 12, bone 40 mm: the block's boxes), the tip 20 mm in.
TEST_F(GuidanceOverlay, LayeredTargetShowsTheAxisTheTargetAndTheDepthGaugeWithTheLayers) {
  const training::Vec3 tip{0.33, 0.0, 0.07 - 0.020};
  EXPECT_TRUE(matches_golden(draw("layered_target", 2, tip, {0.0, 0.0, -1.0}), "guidance_layered_target"));
}

// An assessment run (the task hides the layer names): the same marks, their depths but no names.
TEST_F(GuidanceOverlay, LayeredTargetWithHiddenNamesKeepsTheMarksUnnamed) {
  const training::Vec3 tip{0.33, 0.0, 0.07 - 0.020};
  EXPECT_TRUE(
      matches_golden(draw("layered_target", 2, tip, {0.0, 0.0, -1.0}, true), "guidance_layered_target_hidden_names"));
}

// The epidural's approach: the entry ring on the midline and the axis, the tip 15 mm above the skin.
TEST_F(GuidanceOverlay, EpiduralApproachShowsTheEntryAndTheMidlineAxis) {
  const training::Vec3 tip{0.33, 0.0, 0.07 + 0.015};
  EXPECT_TRUE(matches_golden(draw("epidural", 0, tip, {0.0, 0.0, -1.0}), "guidance_epidural_approach"));
}

}  // namespace
}  // namespace needle::test
