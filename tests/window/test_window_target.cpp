// The swapchain target under Xvfb: frames are presented, a resize recreates the swapchain at
// the new size (new generation, new framebuffers), also at a render scale below 1 (the scene's
// smaller attachments follow, the upscale's framebuffers over the swapchain's images too), and none of it draws a
// validation message.
#include <GLFW/glfw3.h>
#include <gtest/gtest.h>

#include <chrono>
#include <thread>

#include "engine/gpu_device.hpp"
#include "engine/gpu_scene.hpp"
#include "engine/render_target.hpp"
#include "engine/vulkan/target_images.hpp"  // the swapchain's generation
#include "engine/window.hpp"

namespace needle::test {
namespace {

// Draws until a frame is accepted (a resize may make the target skip some), capturing it.
engine::RgbaImage draw_until_presented(engine::SceneRenderer& renderer, engine::WindowTarget& target,
                                       engine::Window& window, const engine::FrameParams& params) {
  engine::RgbaImage image;
  for (int attempt = 0; attempt < 100; ++attempt) {
    window.poll_events();
    if (renderer.draw(target, params, &image)) return image;
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  ADD_FAILURE() << "no frame accepted in 100 attempts";
  return image;
}

void presents_and_follows_a_resize(float render_scale) {
  ASSERT_TRUE(engine::Window::display_available()) << "run under xvfb-run";
  engine::Window window("needle-sim test", 320, 240);
  engine::GpuDevice device(window, {.validation = true, .announce_device = false});
  {
    engine::WindowTarget target(device, window);
    engine::SceneRenderer renderer(device, target, {1, true, true, true, render_scale});
    engine::Scene view;
    view.background = {1.0f, 0.0f, 0.0f};
    engine::GpuScene scene(renderer, engine::Model{}, view);

    engine::RgbaImage first = draw_until_presented(renderer, target, window, scene.frame_params());
    EXPECT_EQ(first.width, 320u);
    EXPECT_EQ(first.height, 240u);
    EXPECT_EQ(first.at(10, 10)[0], 255);  // red background, channels swizzled back from BGRA
    EXPECT_EQ(first.at(10, 10)[2], 0);
    const uint64_t generation = target.images().generation();

    glfwSetWindowSize(window.handle(), 400, 300);
    for (int i = 0; i < 100 && window.framebuffer_extent().width != 400; ++i) {
      window.poll_events();
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    ASSERT_EQ(window.framebuffer_extent().width, 400u);
    engine::RgbaImage second = draw_until_presented(renderer, target, window, scene.frame_params());
    EXPECT_EQ(second.width, 400u);
    EXPECT_EQ(second.height, 300u);
    EXPECT_GT(target.images().generation(), generation);
    for (int i = 0; i < 5; ++i) draw_until_presented(renderer, target, window, scene.frame_params());
    renderer.wait_idle();
  }
  for (const auto& m : device.validation_messages()) ADD_FAILURE() << "Vulkan validation " << m;
}

TEST(WindowTarget, PresentsAndFollowsAResize) { presents_and_follows_a_resize(1.0f); }

TEST(WindowTarget, PresentsAndFollowsAResizeAtHalfRenderScale) { presents_and_follows_a_resize(0.5f); }

}  // namespace
}  // namespace needle::test
