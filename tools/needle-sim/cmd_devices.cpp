// needle-sim devices: what is connected and what each device backend needs.
#include <cstdio>

#include "arg_list.hpp"
#include "command.hpp"
#include "haptics/devices/device_catalog.hpp"

namespace needle::cli {
namespace {

int run_devices(ArgList& args) {
  args.finish();
  for (const auto& b : haptics::list_backends()) {
    std::printf("%-12s %s\n", b.spec.c_str(), b.status.c_str());
    std::printf("%-12s needs: %s\n", "", b.needs.c_str());
  }
  return 0;
}

const CommandRegistrar reg{{"devices",
                            "needle-sim devices\n"
                            "  Lists the haptic device backends (falcon, mouse, replay, sim), what is connected\n"
                            "  now and what each needs (udev rule, firmware file, window).",
                            run_devices}};

}  // namespace
}  // namespace needle::cli
