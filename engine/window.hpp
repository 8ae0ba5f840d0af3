// A window of the window system with no client API: the engine presents to it (a GpuDevice made
// for it, then a WindowTarget), and reads its input in plain types (keys, cursor, wheel, mouse
// buttons, gamepads), so that no caller needs the window system's own headers.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "engine/extent.hpp"

struct GLFWwindow;

namespace needle::engine {

// The keys the application acts on. Keys it does not name arrive as kOther.
enum class Key {
  kOther,
  kUp,
  kDown,
  kLeft,
  kRight,
  kPageUp,
  kPageDown,
  kTab,
  kEnter,
  kEscape,
  kF3,
  kA,
  kB,
  kC,
  kD,
  kE,
  kF,
  kG,
  kH,
  kI,
  kJ,
  kK,
  kL,
  kM,
  kN,
  kO,
  kP,
  kQ,
  kR,
  kS,
  kT,
  kU,
  kV,
  kW,
  kX,
  kY,
  kZ,
};

// A gamepad with a standard mapping (the window system's), as plain values.
struct GamepadInfo {
  int id = 0;        // its slot: the N of gamepad:N
  std::string name;  // as the system names it
};
// Its state in the standard layout: axes left x, left y, right x, right y (in [-1, 1], y down),
// left and right trigger (-1 released to 1 pulled); buttons A, B, X, Y, left and right bumper,
// back, start, guide, left and right thumb, pad up, right, down, left (1 pressed).
struct GamepadReading {
  std::array<float, 6> axes{};
  std::array<unsigned char, 15> buttons{};
};

class Window {
 public:
  // Throws std::runtime_error when there is no display or the system cannot make a window.
  Window(const std::string& title, int width, int height);
  ~Window();
  Window(const Window&) = delete;
  Window& operator=(const Window&) = delete;

  // True when a display can be reached (X11 or Wayland); cheap, and safe to call first.
  static bool display_available();

  // The window system's handle, for the engine's own passes (presentation, the UI backend).
  GLFWwindow* handle() const { return window_; }
  bool should_close() const;
  void request_close();
  void poll_events() const;
  // Blocks until an event arrives (used while minimised).
  void wait_events() const;
  // Framebuffer size in pixels; 0x0 while minimised.
  Extent framebuffer_extent() const;
  // The window's size in screen coordinates (the cursor's), 0x0 while minimised.
  Extent size() const;
  // True once after the framebuffer was resized.
  bool take_resized();
  // The cursor in the window's screen coordinates, (0, 0) at the top left; and put there.
  struct Cursor {
    double x = 0.0, y = 0.0;
  };
  Cursor cursor() const;
  void set_cursor(const Cursor& at);
  // The right mouse button held now; the left one.
  bool right_button_down() const;
  bool left_button_down() const;
  // The space bar held now (the syringe's plunger: docs/DEVICES.md, "The syringe hand").
  bool space_down() const;
  // Scroll-wheel notches since the last call, forward positive; the Up and Down arrow keys
  // count as one notch each, for trackpads and keyboards.
  double take_scroll();
  // A key going down, or repeating while held (the system's key repeat).
  struct KeyPress {
    Key key = Key::kOther;
    bool shift = false;
  };
  // The key presses since the last call, in order (none is lost between two frames, however
  // short). At most kMaxKeyPresses wait; later ones are dropped until they are taken.
  std::vector<KeyPress> take_key_presses();
  // Takes the presses of `key` alone out of those waiting (the window's own keys, before the
  // content's); true when there was one.
  bool take_key_press(Key key);
  static constexpr size_t kMaxKeyPresses = 256;

  // The gamepads present now; display_available() first.
  static std::vector<GamepadInfo> gamepads();
  // Gamepad `id`'s state; nullopt when it is gone.
  static std::optional<GamepadReading> gamepad(int id);

 private:
  GLFWwindow* window_ = nullptr;
  bool resized_ = false;
  double scroll_ = 0.0;
  std::vector<KeyPress> key_presses_;
};

}  // namespace needle::engine
