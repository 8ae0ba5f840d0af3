// The window target under Xvfb, through the swapchain and through X11 shared memory: frames are
// presented, a resize makes the images again at the new size (new generation, new framebuffers),
// also at a render scale below 1 (the scene's smaller attachments follow, the upscale's
// framebuffers over the target's images too), and none of it draws a validation message.
#include <gtest/gtest.h>

#include "engine/gpu_device.hpp"
#include "engine/gpu_scene.hpp"
#include "engine/render_target.hpp"
#include "engine/vulkan/target_images.hpp"  // the images' generation
#include "engine/window.hpp"
#include "window_frames.hpp"

namespace needle::test {
namespace {

using Presentation = engine::WindowTarget::Presentation;

void presents_and_follows_a_resize(float render_scale, Presentation way) {
  ASSERT_TRUE(engine::Window::display_available()) << "run under xvfb-run";
  engine::Window window("needle-sim test", 320, 240);
  engine::GpuDevice device(window, {.validation = true, .announce_device = false});
  {
    engine::WindowTarget target(device, window);
    ASSERT_TRUE(target.set_presentation(way)) << target.presentation_note();
    engine::SceneRenderer renderer(device, target, {1, true, true, true, render_scale});
    engine::Scene view;
    view.background = {1.0f, 0.0f, 0.0f};
    engine::GpuScene scene(renderer, engine::Model{}, view);

    engine::RgbaImage first = draw_until_accepted(renderer, target, window, scene.frame_params());
    EXPECT_EQ(first.width, 320u);
    EXPECT_EQ(first.height, 240u);
    EXPECT_EQ(first.at(10, 10)[0], 255);  // red background, channels swizzled back from BGRA
    EXPECT_EQ(first.at(10, 10)[2], 0);
    const uint64_t generation = target.images().generation();

    ASSERT_TRUE(resize(window, 400, 300));
    engine::RgbaImage second = draw_until_accepted(renderer, target, window, scene.frame_params());
    EXPECT_EQ(second.width, 400u);
    EXPECT_EQ(second.height, 300u);
    EXPECT_GT(target.images().generation(), generation);
    for (int i = 0; i < 5; ++i) draw_until_accepted(renderer, target, window, scene.frame_params());
    renderer.wait_idle();
  }
  for (const auto& m : device.validation_messages()) ADD_FAILURE() << "Vulkan validation " << m;
}

TEST(WindowTarget, PresentsAndFollowsAResize) { presents_and_follows_a_resize(1.0f, Presentation::Fifo); }

TEST(WindowTarget, PresentsAndFollowsAResizeAtHalfRenderScale) {
  presents_and_follows_a_resize(0.5f, Presentation::Fifo);
}

TEST(WindowTarget, PresentsAndFollowsAResizeThroughSharedMemory) {
  presents_and_follows_a_resize(1.0f, Presentation::SharedMemory);
}

TEST(WindowTarget, PresentsAndFollowsAResizeThroughSharedMemoryAtHalfRenderScale) {
  presents_and_follows_a_resize(0.5f, Presentation::SharedMemory);
}

}  // namespace
}  // namespace needle::test
