// The per-tick physics behind the loop: controller, constraint solver and virtual robot
// integration (haptics/control, haptics/sim) plug in through this narrow interface.
#pragma once

#include "haptics/devices/device_io.hpp"
#include "haptics/realtime/tool_snapshot.hpp"

namespace needle::haptics {

class ServoStep {
 public:
  virtual ~ServoStep() = default;
  // Advances the simulation by dt_s (the loop's nominal period, so a replay is
  // deterministic) from this tick's device reading; writes the command for the device and
  // the new state. Must not allocate, lock, block or log.
  virtual void step(const DeviceReading& reading, double dt_s, DeviceCommand& command,
                    ToolSnapshot& state) noexcept = 0;
  // What the device was given after the safety monitor (saturated, rate-limited or ramped down),
  // once per tick after step(): a step that observes the energy at the device's port needs it. The
  // same in a replay, so the replay's observer sees what the run's did.
  virtual void applied(const DeviceCommand& /*command*/) noexcept {}
};

}  // namespace needle::haptics
