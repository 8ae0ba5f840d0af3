#include "haptics/devices/device_catalog.hpp"

#include "haptics/devices/desk_device.hpp"
#include "haptics/devices/falcon/falcon_device.hpp"
#include "haptics/devices/replay_device.hpp"

namespace needle::haptics {

std::unique_ptr<HapticDevice> make_device(const DeviceSpec& spec, const DeviceOptions& options) {
  switch (spec.kind) {
    case DeviceSpec::Kind::kMouse:
    case DeviceSpec::Kind::kKeyboard:
    case DeviceSpec::Kind::kGamepad:
      return std::make_unique<DeskDevice>(spec);
    case DeviceSpec::Kind::kFalcon: {
      falcon::FalconOptions falcon_options;
      falcon_options.firmware_path = options.firmware_path;
      falcon_options.index = spec.index.value_or(0);
      return std::make_unique<falcon::FalconDevice>(falcon_options);
    }
    case DeviceSpec::Kind::kReplay:
      return std::make_unique<ReplayDevice>(spec.file);
    case DeviceSpec::Kind::kSim:
      break;
  }
  throw DeviceError("device " + spec.text() +
                    ": built with its controller step from a scenario by haptics::SimSession, not by make_device");
}

std::unique_ptr<HapticDevice> make_second_falcon(const DeviceSpec& needle, const DeviceOptions& options) {
  if (needle.kind != DeviceSpec::Kind::kFalcon || falcon::find_falcons().count < 2) return nullptr;
  DeviceSpec second = needle;
  second.index = needle.index.value_or(0) == 0 ? 1 : 0;
  return make_device(second, options);
}

std::vector<BackendStatus> list_backends() {
  const falcon::UsbPresence falcons = falcon::find_falcons();
  std::string falcon_status;
  if (!falcons.error.empty()) {
    falcon_status = "USB bus not readable: " + falcons.error;
  } else if (falcons.count == 0) {
    falcon_status = "none connected";
  } else {
    falcon_status = std::to_string(falcons.count) + " connected (falcon:0" +
                    (falcons.count > 1 ? " .. falcon:" + std::to_string(falcons.count - 1) : std::string()) + ")";
  }
  return {
      {"falcon[:N]", falcon_status,
       "Novint Falcon on USB 0403:cb48, read/write access (tools/udev/99-novint-falcon.rules), "
       "and after each power-up --firmware FILE: Novint's firmware image (not shipped, its licence forbids it); in a "
       "task with "
       "a syringe a second Falcon presses its plunger (pushed away from you), else the space bar"},
      {"mouse", "available",
       "a window: the cursor moves the tool, the wheel or Up/Down push it in, the right button held turns it about its "
       "tip; "
       "the left button or the space bar held presses a syringe's plunger; forces shown, not felt"},
      {"keyboard", "available",
       "a window: arrows move the tool, W/S push it in and out, A/D and Q/E turn it about its tip (Shift: fine steps), "
       "the space bar held presses a syringe's plunger; forces shown, not felt"},
      {"gamepad[:N]", "listed by the window (GLFW reports gamepads once it has a display)",
       "a window and a gamepad with a standard mapping: left stick moves the tool, triggers push it in and out, right "
       "stick turns it about its tip, Start resets a fault; with a syringe the left trigger presses its plunger and "
       "the "
       "right trigger draws the tool back while the left bumper is held; forces shown, not felt"},
      {"replay:FILE", "available", "a session recording written by an earlier run"},
      {"sim:SCENARIO", "available",
       "a scenario file (assets/scenarios/*.json): the master model and a simulated operator step with the loop; "
       "needle-sim run --device sim takes the task's scenario with a scripted operator (--operator)"},
  };
}

}  // namespace needle::haptics
