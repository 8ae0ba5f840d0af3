// needle-sim devices: what is connected and what each device backend needs.
#include <cstdio>

#include "command.hpp"
#include "engine/window.hpp"
#include "haptics/devices/device_catalog.hpp"

namespace needle::cli {
namespace {

// With a display, the gamepads GLFW reports now (as the start screen lists them).
std::string gamepads_present(const std::string& without_display) {
  if (!engine::Window::display_available()) return without_display;
  const std::vector<engine::GamepadInfo> pads = engine::Window::gamepads();
  if (pads.empty()) return "none connected (GLFW reports no gamepad with a standard mapping)";
  std::string line = std::to_string(pads.size()) + " connected:";
  for (const engine::GamepadInfo& pad : pads)
    line += " " + haptics::DeviceSpec{haptics::DeviceSpec::Kind::kGamepad, pad.id}.text() + " (" + pad.name + ")";
  return line;
}

int run() {
  for (auto b : haptics::list_backends()) {
    if (b.spec == "gamepad[:N]") b.status = gamepads_present(b.status);
    std::printf("%-12s %s\n", b.spec.c_str(), b.status.c_str());
    std::printf("%-12s needs: %s\n", "", b.needs.c_str());
  }
  return 0;
}

// The options of devices, declared; what runs it once they are parsed.
Runner declare(CLI::App& app) {
  app.footer(
      "Lists the device backends (falcon, mouse, keyboard, gamepad, replay, sim), what is connected now\n"
      "(gamepads when there is a display) and what each needs (udev rule, firmware file, window).");
  return run;
}

const CommandRegistrar reg{{"devices", "the device backends, what is connected now and what each needs", declare}};

}  // namespace
}  // namespace needle::cli
