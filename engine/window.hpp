// A GLFW window with no client API: the engine presents to it (a GpuDevice made for it, then a
// WindowTarget), and reads its input.
#pragma once

#include <string>
#include <vector>

#include "engine/extent.hpp"

struct GLFWwindow;

namespace needle::engine {

class Window {
 public:
  // Throws std::runtime_error when there is no display or GLFW cannot make a window.
  Window(const std::string& title, int width, int height);
  ~Window();
  Window(const Window&) = delete;
  Window& operator=(const Window&) = delete;

  // True when GLFW can reach a display (X11 or Wayland); cheap, and safe to call first.
  static bool display_available();

  GLFWwindow* handle() const { return window_; }
  bool should_close() const;
  void request_close();
  void poll_events() const;
  // Blocks until an event arrives (used while minimised).
  void wait_events() const;
  // Framebuffer size in pixels; 0x0 while minimised.
  Extent framebuffer_extent() const;
  // True once after the framebuffer was resized.
  bool take_resized();
  // The cursor in normalised window coordinates: x right and y up, (0, 0) at the centre,
  // +-1 at the edges (beyond them when the cursor is outside).
  void cursor_normalized(double& x, double& y) const;
  // Scroll-wheel notches since the last call, forward positive; the Up and Down arrow keys
  // count as one notch each, for trackpads and keyboards.
  double take_scroll();
  // A key going down, or repeating while held (the system's key repeat): GLFW's key code.
  struct KeyPress {
    int key = 0;
    bool shift = false;
  };
  // The key presses since the last call, in order (none is lost between two frames, however
  // short). At most kMaxKeyPresses wait; later ones are dropped until they are taken.
  std::vector<KeyPress> take_key_presses();
  static constexpr size_t kMaxKeyPresses = 256;

 private:
  GLFWwindow* window_ = nullptr;
  bool resized_ = false;
  double scroll_ = 0.0;
  std::vector<KeyPress> key_presses_;
};

}  // namespace needle::engine
