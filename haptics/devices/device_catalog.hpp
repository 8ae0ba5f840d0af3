// Device specs as the user types them ("falcon", "falcon:1", "mouse", "keyboard", "gamepad:0",
// "replay:FILE") and what each backend needs, for `needle-sim devices` and the app's --device
// option.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "haptics/devices/haptic_device.hpp"

namespace needle::haptics {

struct DeviceOptions {
  std::string firmware_path;  // falcon: Novint's firmware image, loaded at open()
};

// Builds (does not open) the device for a spec. Throws DeviceError naming the spec and the
// known backends when it is not one of them. `sim` is not built here: it needs the master
// model and the scene, so the app constructs it (docs/DEVICES.md).
std::unique_ptr<HapticDevice> make_device(const std::string& spec, const DeviceOptions& options);

struct BackendStatus {
  std::string spec;    // how to ask for it
  std::string status;  // what is connected or available now
  std::string needs;   // what it requires from the user or the machine
};

// Every backend, probing the USB bus for Falcons (no device is opened). Gamepads are found
// through the window system, by the app (app/desk_input.hpp, present_gamepads).
std::vector<BackendStatus> list_backends();

}  // namespace needle::haptics
