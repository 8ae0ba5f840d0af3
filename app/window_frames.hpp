// What the window commands share: a window with its GPU device and target (saying, as the device
// does, how frames reach it), and the frame count that draws each frame and, for --frames N,
// closes the window after frame N, saving it first when --screenshot names a file (the CLI tests
// under Xvfb use both).
#pragma once

#include <functional>
#include <optional>
#include <string>

#include "app/messages.hpp"
#include "engine/extent.hpp"
#include "engine/gpu_device.hpp"
#include "engine/render_target.hpp"
#include "engine/scene_renderer.hpp"
#include "engine/window.hpp"

namespace needle::app {

struct GpuWindow {
  // Says how frames reach the window ("Window: ...") to `messages`.
  GpuWindow(const std::string& title, engine::Extent size, const Messages& messages);
  // The MSAA samples an interactive window asks for: on a CPU device (lavapipe) 4x costs 1.8 to
  // 3.3x the frame time (docs/BENCHMARKS.md), so there it keeps its frame rate instead.
  int default_msaa_samples() const { return device.is_cpu_device() ? 1 : 4; }

  engine::Window window;
  engine::GpuDevice device;
  engine::WindowTarget target;
};

class WindowFrames {
 public:
  // The screenshot's "wrote FILE (WxH)" goes to `messages`.
  WindowFrames(long frames, std::optional<std::string> screenshot, Messages messages)
      : frames_(frames), screenshot_(std::move(screenshot)), messages_(std::move(messages)) {}

  // Draws one frame with `draw_frame` (which reads it back into its argument when that is set,
  // and says whether the target took a frame); when nothing could be drawn (minimised, resizing)
  // waits for an event instead.
  void draw(engine::Window& window, const std::function<bool(engine::RgbaImage* capture)>& draw_frame);
  long drawn() const { return drawn_; }

 private:
  long frames_;  // 0: until the user closes the window
  std::optional<std::string> screenshot_;
  Messages messages_;
  long drawn_ = 0;
};

}  // namespace needle::app
