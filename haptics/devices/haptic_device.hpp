// The one interface every haptic device backend implements (falcon, mouse, replay, sim).
// open/close/home run outside the real-time loop and may throw DeviceError; read and write
// run in every tick and must not allocate, lock or log beyond the device's own I/O.
#pragma once

#include <stdexcept>
#include <string>

#include "haptics/devices/device_io.hpp"

namespace needle::haptics {

// A device that cannot be opened, homed or found. what() names the device and the cause.
struct DeviceError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

struct DeviceCapabilities {
  std::string name;  // "falcon", "mouse", "replay:FILE", ...
  CommandSpace command_space = CommandSpace::kNone;
  uint32_t actuated_axes = 0;
  uint32_t joint_count = 0;                     // joints reported in DeviceReading::joint_rad
  double workspace_min_m[3] = {0.0, 0.0, 0.0};  // axis-aligned box around the reachable space, device frame
  double workspace_max_m[3] = {0.0, 0.0, 0.0};
  double max_force_n = 0.0;  // continuous, at the handle
  double max_torque_nm[kMaxDeviceJoints] = {};
  double max_stiffness_n_per_m = 0.0;  // stable virtual-wall stiffness at 1 kHz
  bool senses_force = false;
};

class HapticDevice {
 public:
  virtual ~HapticDevice() = default;

  virtual void open() = 0;
  virtual void close() noexcept = 0;
  // Homing or calibration; blocks until done or throws DeviceError.
  virtual void home() = 0;
  virtual const DeviceCapabilities& capabilities() const noexcept = 0;

  // Real-time: fills `out` with the newest reading (sequence unchanged when nothing new,
  // connected = 0 when the device is gone).
  virtual void read(DeviceReading& out) noexcept = 0;
  // Real-time: sends the command (already saturated by the safety monitor).
  virtual void write(const DeviceCommand& command) noexcept = 0;
  // Real-time, after write(): whether the device applied less than it was written, at a force limit of
  // its own (the simulated Omni's at the tip; a replay: whether the recorded device did). The loop
  // marks the tick (ToolSnapshot::limits, kLimitForce) so that no clipping goes unsaid.
  virtual bool held_back() const noexcept { return false; }
};

}  // namespace needle::haptics
