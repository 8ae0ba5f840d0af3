// Why the safety monitor latched a fault. Stored as uint32_t in ToolSnapshot::fault.
#pragma once

#include <cstdint>

namespace needle::haptics {

enum class FaultCause : uint32_t {
  kNone = 0,
  kNonFinite = 1,        // NaN or Inf in the reading, the simulation state or the command
  kDisconnected = 2,     // the device reports it is gone
  kStaleReading = 3,     // no fresh reading for SafetyLimits::stale_ticks ticks
  kFrozenReading = 4,    // readings bit-identical under force for frozen_ticks ticks
  kMissedDeadlines = 5,  // missed_deadline_streak overruns in a row
  kEnergyGrowth = 6,     // the simulation gave the operator more than max_generated_energy_j
};

// "non-finite value", "device disconnected", ...
const char* fault_cause_name(FaultCause cause) noexcept;

}  // namespace needle::haptics
