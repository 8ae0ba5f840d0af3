// The window's side of the desk devices (docs/DEVICES.md, "Desk devices"): each frame the app
// reads the mouse, the keys or a gamepad through engine::Window and hands plain values to the
// device's mapping (haptics/devices/desk_mapping.hpp), whose pose goes to the device lock-free. The
// mappings below it are tested without a display.
#pragma once

#include <chrono>
#include <optional>
#include <string>
#include <vector>

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
  // The mouse: puts the cursor on `world` (the tool's start) as `camera` shows it in `window`, so
  // that the tip starts under the cursor; the first frame's reading is then the tool's start.
  void place_cursor(engine::Window& window, const engine::Camera& camera, const glm::vec3& world);
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
  bool turning_ = false;          // the mouse's turning button is held
  engine::Window::Cursor turn_from_;  // where the cursor was when it went down
  bool gamepad_ = false;
  int gamepad_id_ = 0;
  std::optional<std::chrono::steady_clock::time_point> last_frame_;
};

}  // namespace needle::app
