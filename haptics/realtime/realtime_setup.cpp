#include "haptics/realtime/realtime_setup.hpp"

#include <pthread.h>
#include <sched.h>
#include <sys/mman.h>
#include <sys/resource.h>
#include <unistd.h>

#include <cstring>
#include <string>

namespace needle::haptics {
namespace {

std::string outcome(bool ok, int err) {
  return ok ? "granted" : std::string("not granted (") + std::strerror(err) + ")";
}

}  // namespace

RealtimeReport request_realtime(const RealtimeRequest& request) {
  RealtimeReport report;
  std::string parts;
  auto add = [&parts](const std::string& what) { parts += (parts.empty() ? "" : "; ") + what; };

  if (request.fifo) {
    sched_param param{};
    param.sched_priority = request.priority;
    const int err = pthread_setschedparam(pthread_self(), SCHED_FIFO, &param);
    report.fifo = err == 0;
    add("SCHED_FIFO " + std::to_string(request.priority) + " " + outcome(report.fifo, err));
  }
  if (request.lock_memory) {
    // With a finite RLIMIT_MEMLOCK, MCL_FUTURE would make later allocations fail once the
    // limit is reached: lock only when the limit cannot bite.
    rlimit limit{};
    getrlimit(RLIMIT_MEMLOCK, &limit);
    if (limit.rlim_cur == RLIM_INFINITY || geteuid() == 0) {
      report.memory_locked = mlockall(MCL_CURRENT | MCL_FUTURE) == 0;
      add("mlockall " + outcome(report.memory_locked, errno));
    } else {
      add("mlockall not granted (RLIMIT_MEMLOCK is " + std::to_string(limit.rlim_cur / 1024) + " KiB, not unlimited)");
    }
  }
  const long cpus = sysconf(_SC_NPROCESSORS_ONLN);
  const int cpu = request.cpu >= 0 ? request.cpu : static_cast<int>(cpus - 1);
  cpu_set_t set;
  CPU_ZERO(&set);
  CPU_SET(cpu, &set);
  const int err = pthread_setaffinity_np(pthread_self(), sizeof set, &set);
  report.pinned = err == 0;
  add("CPU " + std::to_string(cpu) + " affinity " + outcome(report.pinned, err));
  report.line = "real-time: " + parts;
  return report;
}

}  // namespace needle::haptics
