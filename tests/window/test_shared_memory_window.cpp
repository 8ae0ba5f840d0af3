// A CPU device's window through X11 shared memory, under Xvfb: what the X server holds in the
// window (read back with XGetImage, independently of our capture) is the frame drawn, pixel for
// pixel, once the next frame has begun (a frame is shown when the next is acquired), at the first
// size and after a resize to an odd width; switching to the swapchain and back keeps drawing it;
// none of it draws a validation message.
#include <gtest/gtest.h>

#include "engine/gpu_device.hpp"
#include "engine/gpu_scene.hpp"
#include "engine/render_target.hpp"
#include "engine/vulkan/command_buffer.hpp"  // the overlay's command buffer
#include "engine/window.hpp"
#include "window_frames.hpp"

// Last: Xlib's macros.
#define GLFW_EXPOSE_NATIVE_X11
#include <GLFW/glfw3.h>
#include <GLFW/glfw3native.h>
#include <X11/Xutil.h>

namespace needle::test {
namespace {

using Presentation = engine::WindowTarget::Presentation;

// A red frame with a green rectangle at (37, 53), 100 x 70 pixels, drawn by the overlay.
constexpr int kRectX = 37, kRectY = 53, kRectW = 100, kRectH = 70;
engine::FrameParams red_with_green_rectangle(engine::GpuScene& scene) {
  engine::FrameParams params = scene.frame_params();
  params.overlay = [](const engine::CommandBuffer& cmd) {
    VkClearAttachment green{VK_IMAGE_ASPECT_COLOR_BIT, 0, {}};
    green.clearValue.color = {{0.0f, 1.0f, 0.0f, 1.0f}};
    const VkClearRect rect{{{kRectX, kRectY}, {uint32_t(kRectW), uint32_t(kRectH)}}, 0, 1};
    vkCmdClearAttachments(cmd.handle, 1, &green, 1, &rect);
  };
  return params;
}

// The window's pixels as the X server holds them, as RGBA (the visual is 32-bit BGRX).
engine::RgbaImage server_pixels(const engine::Window& window, uint32_t width, uint32_t height) {
  Display* display = glfwGetX11Display();
  XImage* image = XGetImage(display, glfwGetX11Window(window.handle()), 0, 0, width, height, AllPlanes, ZPixmap);
  engine::RgbaImage out{width, height, std::vector<uint8_t>(size_t(width) * height * 4)};
  if (!image) {
    ADD_FAILURE() << "XGetImage failed";
    return out;
  }
  for (uint32_t y = 0; y < height; ++y) {
    for (uint32_t x = 0; x < width; ++x) {
      const unsigned long p = XGetPixel(image, int(x), int(y));
      uint8_t* o = &out.pixels[(size_t(y) * width + x) * 4];
      o[0] = uint8_t(p >> 16);
      o[1] = uint8_t(p >> 8);
      o[2] = uint8_t(p);
      o[3] = 255;
    }
  }
  XDestroyImage(image);
  return out;
}

// The frame drawn is the picture asked for, and once the next frame has begun the server shows
// exactly it.
void expect_shown(engine::SceneRenderer& renderer, engine::WindowTarget& target, engine::Window& window,
                  const engine::FrameParams& params, uint32_t width, uint32_t height) {
  const engine::RgbaImage drawn = draw_until_accepted(renderer, target, window, params);
  draw_until_accepted(renderer, target, window, params);
  ASSERT_EQ(drawn.width, width);
  ASSERT_EQ(drawn.height, height);
  EXPECT_EQ(drawn.at(5, 5)[0], 255);  // red outside the rectangle
  EXPECT_EQ(drawn.at(5, 5)[1], 0);
  EXPECT_EQ(drawn.at(kRectX, kRectY)[1], 255);  // green from its corner
  EXPECT_EQ(drawn.at(kRectX + kRectW - 1, kRectY + kRectH - 1)[0], 0);
  EXPECT_EQ(drawn.at(kRectX + kRectW, kRectY + kRectH)[0], 255);  // and red after it
  EXPECT_EQ(drawn.at(width - 1, height - 1)[0], 255);
  const engine::RgbaImage shown = server_pixels(window, width, height);
  size_t differing = 0;
  for (size_t i = 0; i < shown.pixels.size(); i += 4)
    for (int c = 0; c < 3; ++c) differing += shown.pixels[i + c] != drawn.pixels[i + c] ? 1 : 0;
  EXPECT_EQ(differing, 0u) << "channels that differ between the frame drawn and the window's pixels";
}

TEST(SharedMemoryWindow, TheServerShowsTheFrameDrawnAlsoAfterAResizeAndASwitchToTheSwapchainAndBack) {
  ASSERT_TRUE(engine::Window::display_available()) << "run under xvfb-run";
  engine::Window window("needle-sim test", 320, 240);
  engine::GpuDevice device(window, {.validation = true, .announce_device = false});
  ASSERT_TRUE(device.is_cpu_device()) << "the window suite runs on lavapipe";
  {
    engine::WindowTarget target(device, window);
    ASSERT_EQ(target.presentation(), Presentation::SharedMemory) << target.presentation_note();
    engine::SceneRenderer renderer(device, target, {1, true, true, true, 1.0f});
    engine::Scene view;
    view.background = {1.0f, 0.0f, 0.0f};
    engine::GpuScene scene(renderer, engine::Model{}, view);
    const engine::FrameParams params = red_with_green_rectangle(scene);
    expect_shown(renderer, target, window, params, 320, 240);

    // An odd width: rows whose pitch the device may pad.
    ASSERT_TRUE(resize(window, 401, 301));
    expect_shown(renderer, target, window, params, 401, 301);

    ASSERT_TRUE(target.set_presentation(Presentation::Fifo));
    EXPECT_EQ(target.presentation(), Presentation::Fifo);
    engine::RgbaImage through_swapchain = draw_until_accepted(renderer, target, window, params);
    EXPECT_EQ(through_swapchain.width, 401u);
    EXPECT_EQ(through_swapchain.at(kRectX, kRectY)[1], 255);
    ASSERT_TRUE(target.set_presentation(Presentation::SharedMemory));
    for (int i = 0; i < 3; ++i) draw_until_accepted(renderer, target, window, params);
    expect_shown(renderer, target, window, params, 401, 301);
    renderer.wait_idle();
  }
  for (const auto& m : device.validation_messages()) ADD_FAILURE() << "Vulkan validation " << m;
}

}  // namespace
}  // namespace needle::test
