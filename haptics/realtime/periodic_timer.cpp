#include "haptics/realtime/periodic_timer.hpp"

#include <cerrno>
#include <ctime>

namespace needle::haptics {
namespace {

constexpr int64_t kNsPerS = 1'000'000'000;

}  // namespace

int64_t monotonic_ns() noexcept {
  timespec ts{};
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return static_cast<int64_t>(ts.tv_sec) * kNsPerS + ts.tv_nsec;
}

void PeriodicTimer::start() noexcept { deadline_ns_ = monotonic_ns() + period_ns_; }

int64_t PeriodicTimer::wait() noexcept {
  timespec ts{};
  ts.tv_sec = static_cast<time_t>(deadline_ns_ / kNsPerS);
  ts.tv_nsec = static_cast<long>(deadline_ns_ % kNsPerS);
  while (clock_nanosleep(CLOCK_MONOTONIC, TIMER_ABSTIME, &ts, nullptr) == EINTR) {
  }
  return monotonic_ns();
}

bool PeriodicTimer::advance(int64_t end_ns) noexcept {
  deadline_ns_ += period_ns_;
  if (end_ns <= deadline_ns_) return false;
  deadline_ns_ = end_ns;
  return true;
}

}  // namespace needle::haptics
