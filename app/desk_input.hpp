// The window's side of the desk devices (docs/DEVICES.md, "Desk devices"): each frame the app
// reads the mouse, the keys or a gamepad through engine::Window and hands plain values to the
// device's mapping (haptics/devices/desk_mapping.hpp), whose pose goes to the device lock-free. The
// mappings below it are tested without a display.
#pragma once

#include <array>
#include <chrono>
#include <optional>
#include <string>
#include <vector>

#include "app/session_rig.hpp"
#include "engine/scene.hpp"
#include "engine/window.hpp"
#include "haptics/devices/desk_mapping.hpp"
#include "haptics/devices/device_spec.hpp"

namespace needle::app {

// The gamepad slot a gamepad spec names ("gamepad": the first present, engine::Window::gamepads()). Throws
// std::runtime_error saying what to do when it is not there.
int gamepad_id(const haptics::DeviceSpec& spec);
// Before a session opens on `spec`: the gamepad it names is present (gamepad_id's error
// otherwise); nothing to check for the other devices here (a Falcon is found when it opens).
void check_present(const haptics::DeviceSpec& spec);

// How `camera` shows a tool starting at `start` to the mouse (haptics::MouseView): its field of
// view and the start's distance along the view.
haptics::MouseView mouse_view(const engine::Camera& camera, const ToolStart& start);
// The needle's direction as the wrist of `pose` turns the start's (haptics::wrist_direction, as the
// coupling turns it), in device axes: where the wheel, W and S and the triggers push before the
// needle's own axis is known (DeskInput::set_needle_axis).
haptics::NeedleDirection needle_direction(const ToolStart& start, const haptics::DeskPose& pose);
// The needle's axis now (world frame, unit) in device axes.
haptics::NeedleDirection needle_direction(const ToolStart& start, const std::array<double, 3>& axis);

class DeskInput {
 public:
  // For the desk device `device` (mouse, keyboard, gamepad[:N]); `syringe`: the task has a syringe,
  // whose plunger a gamepad's left trigger presses (SyringeInput). Throws std::runtime_error when a
  // gamepad spec names none that is present.
  explicit DeskInput(haptics::DeskDevice& device, bool syringe = false);

  // One frame of input: the window's cursor, wheel and gamepad, and the frame's key presses
  // (taken from the window by the caller, who may act on some too). `pointer_on_panel`: the
  // cursor is over a panel, whose clicks and motion are the panel's, so the mouse leaves the
  // needle where it is.
  void frame(engine::Window& window, const std::vector<engine::Window::KeyPress>& keys, bool pointer_on_panel);
  // The needle's axis now (world frame, the newest state's): the wheel, W and S and the triggers
  // push along it, as a needle is pushed along itself (in tissue it cannot go sideways), rather
  // than along the wrist's target, which the needle may lag.
  void set_needle_axis(const std::array<double, 3>& axis) { axis_ = axis; }
  // Where the tool starts and how `camera` shows it: the wheel, W and S and the triggers push along
  // the needle from then on; the mouse maps the cursor through that view (haptics::MouseView) and
  // the cursor is put on the tool's start, so the tip starts, and comes to rest, under it. The first
  // frame's reading is then the tool's start.
  void start_at(engine::Window& window, const engine::Camera& camera, const ToolStart& start);
  // True once after each press of the gamepad's reset button.
  bool take_fault_reset() { return gamepad_ && pad_.take_fault_reset(); }
  // What moves the needle, in one line for the panel (with a syringe, what presses its plunger too).
  static std::string help(haptics::DeviceSpec::Kind kind, bool syringe = false);

 private:
  haptics::DeskDevice& device_;
  enum class Kind { kMouse, kKeyboard, kGamepad } kind_;
  haptics::MouseMapping mouse_;
  haptics::KeyboardMapping keys_;
  haptics::GamepadMapping pad_;
  std::optional<ToolStart> start_;             // the needle's start direction and the view's axes, once known
  std::optional<std::array<double, 3>> axis_;  // the needle's axis now, once a state has come
  bool turning_ = false;                       // the mouse's turning button is held
  engine::Window::Cursor turn_from_;           // where the cursor was when it went down
  bool gamepad_ = false;
  int gamepad_id_ = 0;
  std::optional<std::chrono::steady_clock::time_point> last_frame_;
};

}  // namespace needle::app
