// Everything one tick produced, pushed on the SPSC ring for the recorder and the scoring.
#pragma once

#include <cstdint>

#include "haptics/devices/device_io.hpp"
#include "haptics/realtime/tool_snapshot.hpp"

namespace needle::haptics {

struct TickSample {
  uint64_t tick = 0;
  int64_t time_ns = 0;      // wake time, CLOCK_MONOTONIC
  uint64_t period_ns = 0;   // since the previous wake
  uint64_t compute_ns = 0;  // read, step, safety, write
  DeviceReading reading;
  DeviceCommand command;  // after the safety monitor: what the device received
  ToolSnapshot state;
};

}  // namespace needle::haptics
