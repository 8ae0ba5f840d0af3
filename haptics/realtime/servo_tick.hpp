// One tick of the haptic loop, separate from the thread so tests and benchmarks can run
// it directly: read the device, run the step, pass the command through the safety monitor,
// write it, publish the snapshot and push the sample. No allocation, no lock, no I/O but
// the device's own.
#pragma once

#include <cstdint>

#include "haptics/devices/haptic_device.hpp"
#include "haptics/realtime/servo_step.hpp"
#include "haptics/realtime/tick_sample.hpp"
#include "haptics/realtime/tool_snapshot.hpp"
#include "haptics/safety/safety_monitor.hpp"
#include "haptics/sync/seqlock.hpp"
#include "haptics/sync/spsc_ring.hpp"

namespace needle::haptics {

struct TickTiming {
  uint64_t tick = 0;
  int64_t wake_ns = 0;
  uint64_t period_ns = 0;
  bool previous_overran = false;
};

class ServoTick {
 public:
  ServoTick(HapticDevice& device, SafetyMonitor& safety, SeqLock<ToolSnapshot>& snapshots,
            SpscRing<TickSample>& samples) noexcept;

  // nullptr: no scene; the device is read and commanded to zero force.
  void set_step(ServoStep* step) noexcept { step_ = step; }
  ServoStep* step() const noexcept { return step_; }

  // Runs one tick; returns its compute time in nanoseconds (wake to written command).
  uint64_t run(const TickTiming& timing, double dt_s) noexcept;

  const TickSample& last_sample() const noexcept { return sample_; }

 private:
  HapticDevice& device_;
  SafetyMonitor& safety_;
  SeqLock<ToolSnapshot>& snapshots_;
  SpscRing<TickSample>& samples_;
  ServoStep* step_ = nullptr;
  TickSample sample_;  // scratch, reused every tick
};

}  // namespace needle::haptics
