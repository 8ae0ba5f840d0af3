// What the window tests share: drawing until the target takes a frame (a resize may make it skip
// some), and resizing the window and waiting until its framebuffer follows.
#pragma once

#include <GLFW/glfw3.h>
#include <gtest/gtest.h>

#include <chrono>
#include <thread>

#include "engine/render_target.hpp"
#include "engine/scene_renderer.hpp"
#include "engine/window.hpp"

namespace needle::test {

// The frame drawn (captured) once the target took one.
inline engine::RgbaImage draw_until_accepted(engine::SceneRenderer& renderer, engine::WindowTarget& target,
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

// True once the framebuffer is `width` pixels wide (within a second).
inline bool resize(engine::Window& window, int width, int height) {
  glfwSetWindowSize(window.handle(), width, height);
  for (int i = 0; i < 100 && window.framebuffer_extent().width != uint32_t(width); ++i) {
    window.poll_events();
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  return window.framebuffer_extent().width == uint32_t(width);
}

}  // namespace needle::test
