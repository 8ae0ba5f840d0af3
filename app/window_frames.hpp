// What the window commands share: a window with its Vulkan context and swapchain target, and
// the frame count that draws each frame and, for --frames N, closes the window after frame N,
// saving it first when --screenshot names a file (the CLI tests under Xvfb use both).
#pragma once

#include <optional>
#include <string>

#include "engine/extent.hpp"
#include "engine/scene_renderer.hpp"
#include "engine/vulkan_context.hpp"
#include "engine/window.hpp"
#include "engine/window_target.hpp"

namespace needle::app {

struct VulkanWindow {
  VulkanWindow(const std::string& title, engine::Extent size);
  // On a CPU device (lavapipe) 4x MSAA costs 1.8 to 3.3x the frame time (docs/BENCHMARKS.md).
  bool cpu_device() const { return context.properties().deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU; }

  engine::Window window;
  engine::VulkanContext context;
  engine::WindowTarget target;
};

class WindowFrames {
 public:
  WindowFrames(long frames, std::optional<std::string> screenshot) : frames_(frames), screenshot_(std::move(screenshot)) {}

  // Draws one frame; when nothing could be drawn (minimised, resizing) waits for an event instead.
  void draw(engine::Window& window, engine::SceneRenderer& renderer, engine::RenderTarget& target,
            const engine::FrameParams& params);
  long drawn() const { return drawn_; }

 private:
  long frames_;  // 0: until the user closes the window
  std::optional<std::string> screenshot_;
  long drawn_ = 0;
};

}  // namespace needle::app
