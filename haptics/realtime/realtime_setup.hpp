// Asks the OS for what a servo thread wants: SCHED_FIFO priority, locked memory and a CPU
// of its own. Each is optional; the report names what was granted and what was not, in one
// line, so the user knows why timing may suffer.
#pragma once

#include <string>

namespace needle::haptics {

struct RealtimeRequest {
  bool fifo = true;
  int priority = 80;
  bool lock_memory = true;
  int cpu = -1;  // -1: the last CPU
};

struct RealtimeReport {
  bool fifo = false;
  bool memory_locked = false;
  bool pinned = false;
  std::string line;  // "real-time: SCHED_FIFO 80 granted; mlockall not granted (Operation not permitted); ..."
};

// Applies to the calling thread (mlockall to the whole process).
RealtimeReport request_realtime(const RealtimeRequest& request);

}  // namespace needle::haptics
