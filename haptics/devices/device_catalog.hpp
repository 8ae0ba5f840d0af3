// The device a spec names (haptics/devices/device_spec.hpp), built; and what each backend needs,
// for `needle-sim devices`.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "haptics/devices/device_spec.hpp"
#include "haptics/devices/haptic_device.hpp"

namespace needle::haptics {

struct DeviceOptions {
  std::string firmware_path;  // falcon: Novint's firmware image, loaded at open()
};

// Builds (does not open) the device a spec names. `sim` is not built here: it needs the master
// model and the scene, so haptics::SimSession builds it with its step (DeviceError).
std::unique_ptr<HapticDevice> make_device(const DeviceSpec& spec, const DeviceOptions& options);

// The syringe hand's Falcon beside the needle's (docs/DEVICES.md, "The syringe hand"): when `needle`
// is a Falcon and at least two are on the bus, the other one (falcon:1 for falcon or falcon:0, else
// falcon:0), built; nullptr otherwise.
std::unique_ptr<HapticDevice> make_second_falcon(const DeviceSpec& needle, const DeviceOptions& options);

struct BackendStatus {
  std::string spec;    // how to ask for it
  std::string status;  // what is connected or available now
  std::string needs;   // what it requires from the user or the machine
};

// Every backend, probing the USB bus for Falcons (no device is opened). Gamepads are found
// through the window system, by the app (app/desk_input.hpp, present_gamepads).
std::vector<BackendStatus> list_backends();

}  // namespace needle::haptics
