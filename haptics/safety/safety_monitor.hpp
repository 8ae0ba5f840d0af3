// Safety in the loop: every command passes through here between the controller and the
// device. Saturation to the device's limit and a rate limit on force change always apply;
// on a fault the monitor latches, ramps the output linearly to zero within ramp_ticks ticks
// and keeps it there until reset() (the loop's ResetFault command). Allocation-free.
#pragma once

#include <cstdint>

#include "haptics/devices/device_io.hpp"
#include "haptics/devices/haptic_device.hpp"
#include "haptics/realtime/tool_snapshot.hpp"
#include "haptics/safety/fault_cause.hpp"

namespace needle::haptics {

struct SafetyLimits {
  double max_force_n = 0.0;                     // norm of the task-space force
  double max_torque_nm[kMaxDeviceJoints] = {};  // per joint
  double max_force_rate_n_per_s = 1000.0;       // 1 N per tick at 1 kHz
  double max_torque_rate_nm_per_s = 100.0;
  uint32_t ramp_ticks = 20;   // output is zero this many ticks after the fault
  uint32_t stale_ticks = 20;  // consecutive ticks without a fresh reading
  // Consecutive bit-identical readings while pushing at least frozen_min_force_n: a hand
  // holding a handle against a force trembles (0.05 to 0.5 mm at 8 to 12 Hz) by more than an
  // encoder count (0.04 mm on the Falcon), so 5 s (at 1 kHz) without a change means the
  // encoders or their transport stopped.
  uint32_t frozen_ticks = 5000;
  double frozen_min_force_n = 1.0;
  uint32_t missed_deadline_streak = 10;
  double max_generated_energy_j = 1.0;  // passivity observer bound
};

// The device's own limits with the default fault thresholds.
SafetyLimits safety_limits_for(const DeviceCapabilities& capabilities);

class SafetyMonitor {
 public:
  explicit SafetyMonitor(const SafetyLimits& limits);

  // One tick: checks the tick's inputs, latches a fault if one is found, and replaces
  // `command` by what may be sent (saturated and rate-limited, or the fault ramp).
  // `deadline_missed` tells whether the previous tick overran.
  void apply(uint64_t tick, const DeviceReading& reading, const ToolSnapshot& state, bool deadline_missed, double dt_s,
             DeviceCommand& command) noexcept;

  void reset() noexcept;

  FaultCause fault() const noexcept { return fault_; }
  uint64_t fault_tick() const noexcept { return fault_tick_; }
  // Net work the device has done on the operator since the last reset, in joules
  // (Hannaford and Ryu's passivity observer; positive means the simulation generated energy).
  double generated_energy_j() const noexcept { return energy_j_; }
  // What the last apply() held back: kLimitForce and kLimitRate bits (tool_snapshot.hpp), 0 when the
  // command passed unchanged or a fault's ramp replaced it.
  uint32_t limited() const noexcept { return limited_; }
  const SafetyLimits& limits() const noexcept { return limits_; }

 private:
  FaultCause detect(const DeviceReading& reading, const ToolSnapshot& state, bool deadline_missed,
                    const DeviceCommand& command) noexcept;
  void observe_energy(const DeviceReading& reading) noexcept;
  // Saturates and rate-limits `command`; returns the kLimit* bits of what it changed.
  uint32_t shape(double dt_s, DeviceCommand& command) const noexcept;

  SafetyLimits limits_;
  FaultCause fault_ = FaultCause::kNone;
  uint64_t fault_tick_ = 0;
  uint32_t ticks_since_fault_ = 0;
  DeviceCommand ramp_from_{};
  DeviceCommand last_output_{};
  DeviceReading last_reading_{};
  bool have_last_reading_ = false;
  uint32_t stale_count_ = 0;
  uint32_t frozen_count_ = 0;
  uint32_t missed_count_ = 0;
  double energy_j_ = 0.0;
  uint32_t limited_ = 0;
};

}  // namespace needle::haptics
