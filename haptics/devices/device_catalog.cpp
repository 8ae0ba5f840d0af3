#include "haptics/devices/device_catalog.hpp"

#include "haptics/devices/falcon/falcon_device.hpp"
#include "haptics/devices/mouse_device.hpp"
#include "haptics/devices/replay_device.hpp"

namespace needle::haptics {
namespace {

constexpr const char* kKnown = "expected falcon, falcon:N, mouse or replay:FILE";

bool starts_with(const std::string& s, const std::string& prefix) { return s.rfind(prefix, 0) == 0; }

int parse_index(const std::string& spec, const std::string& digits) {
  if (digits.empty() || digits.size() > 3 || digits.find_first_not_of("0123456789") != std::string::npos)
    throw DeviceError("device " + spec + ": falcon index must be a number, e.g. falcon:1");
  return std::stoi(digits);
}

}  // namespace

std::unique_ptr<HapticDevice> make_device(const std::string& spec, const DeviceOptions& options) {
  if (spec == "mouse") return std::make_unique<MouseDevice>();
  if (spec == "falcon" || starts_with(spec, "falcon:")) {
    falcon::FalconOptions falcon_options;
    falcon_options.firmware_path = options.firmware_path;
    if (spec != "falcon") falcon_options.index = parse_index(spec, spec.substr(7));
    return std::make_unique<falcon::FalconDevice>(falcon_options);
  }
  if (starts_with(spec, "replay:")) {
    if (spec.size() == 7) throw DeviceError("device replay:: expected a recording file after replay:");
    return std::make_unique<ReplayDevice>(spec.substr(7));
  }
  if (spec == "sim" || starts_with(spec, "sim:"))
    throw DeviceError("device " + spec + ": built with its controller step from a scenario by haptics::SimSession, not by make_device");
  throw DeviceError("device " + spec + ": unknown, " + kKnown);
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
       "and after each power-up --firmware FILE: Novint's firmware image (not shipped, its licence forbids it)"},
      {"mouse", "available",
       "a window (needle-sim run --device mouse): cursor moves the tool, scroll or Up/Down set depth; forces shown, not felt"},
      {"replay:FILE", "available", "a session recording written by an earlier run"},
      {"sim:SCENARIO", "available",
       "a scenario file (assets/scenarios/*.json): the master model and a simulated operator step with the loop; "
       "needle-sim run --device sim takes the task's scenario with a scripted operator (--operator)"},
  };
}

}  // namespace needle::haptics
