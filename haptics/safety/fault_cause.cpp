#include "haptics/safety/fault_cause.hpp"

namespace needle::haptics {

const char* fault_cause_name(FaultCause cause) noexcept {
  switch (cause) {
    case FaultCause::kNone:
      return "none";
    case FaultCause::kNonFinite:
      return "non-finite value (NaN or Inf) in reading, state or command";
    case FaultCause::kDisconnected:
      return "device disconnected";
    case FaultCause::kStaleReading:
      return "stale readings (device delivered nothing new)";
    case FaultCause::kFrozenReading:
      return "frozen readings (identical values under force)";
    case FaultCause::kMissedDeadlines:
      return "streak of missed deadlines";
    case FaultCause::kEnergyGrowth:
      return "energy growth beyond bound (simulation not passive)";
  }
  return "unknown";
}

}  // namespace needle::haptics
