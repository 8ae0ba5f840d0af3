// The device a session runs on, as a user names it (`run --device`, the settings file, a
// recording's header): parsed and checked here, and only here, and printed back in the same form,
// so that parse(spec.text()) == spec (docs/DEVICES.md).
//
//   sim            the simulated master and a scripted operator (sim:SCENARIO: a scenario's own)
//   mouse          the desk devices: the trainee moves the needle in the window
//   keyboard
//   gamepad[:N]    GLFW's joystick N (0..15); without N the first present
//   falcon[:N]     Novint Falcon N on the USB bus (0..15); without N the first
//   replay:FILE    a recorded session played back
#pragma once

#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>

namespace needle::haptics {

// A device spec that names no device. what(): "device 'TEXT': what is wrong (expected ...)".
struct DeviceSpecError : std::invalid_argument {
  using std::invalid_argument::invalid_argument;
};

// The forms a spec takes, for messages and help.
inline constexpr const char* kDeviceSpecForms = "sim, mouse, keyboard, gamepad[:N], falcon[:N] or replay:FILE";
// The highest N of gamepad:N and falcon:N: GLFW has 16 joystick slots (GLFW_JOYSTICK_LAST = 15);
// the Falcon's the same, a design value (a station has one or two).
inline constexpr int kMaxDeviceIndex = 15;

struct DeviceSpec {
  enum class Kind { kSim, kMouse, kKeyboard, kGamepad, kFalcon, kReplay };

  Kind kind = Kind::kSim;
  std::optional<int> index;  // gamepad:N, falcon:N; nullopt: the first present
  std::string file;          // replay:FILE (never empty); sim:SCENARIO (empty: the task's scenario)

  // Throws DeviceSpecError naming the text, what is wrong and the forms above.
  static DeviceSpec parse(std::string_view text);
  // The spec as parse() reads it: "sim", "gamepad:1", "replay:/data/a.nrec".
  std::string text() const;

  // mouse, keyboard, gamepad: a haptics::DeskDevice whose pose the window sets.
  bool desk() const { return kind == Kind::kMouse || kind == Kind::kKeyboard || kind == Kind::kGamepad; }
  // Moved by a person in real time (the desk devices and the Falcon): it needs the window.
  bool live() const { return desk() || kind == Kind::kFalcon; }

  bool operator==(const DeviceSpec&) const = default;
};

}  // namespace needle::haptics
