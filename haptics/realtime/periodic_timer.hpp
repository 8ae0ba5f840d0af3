// Absolute-deadline periodic wake-ups on CLOCK_MONOTONIC (clock_nanosleep with
// TIMER_ABSTIME, so sleeping never accumulates drift). Shared by the haptic loop and the
// bare baseline loop of `needle-sim bench loop`, so both are timed the same way.
#pragma once

#include <cstdint>

namespace needle::haptics {

// CLOCK_MONOTONIC in nanoseconds (vDSO: no system call).
int64_t monotonic_ns() noexcept;

class PeriodicTimer {
 public:
  explicit PeriodicTimer(int64_t period_ns) noexcept : period_ns_(period_ns) {}

  // The first deadline is one period from now.
  void start() noexcept;
  // Sleeps until the current deadline; returns the wake time.
  int64_t wait() noexcept;
  // Call when the tick's work is done: moves the deadline one period on. Returns true (an
  // overrun) when the work ended after that next deadline; the schedule then restarts from
  // `end_ns` instead of bursting to catch up.
  bool advance(int64_t end_ns) noexcept;

  void set_period(int64_t period_ns) noexcept { period_ns_ = period_ns; }
  int64_t period_ns() const noexcept { return period_ns_; }

 private:
  int64_t period_ns_;
  int64_t deadline_ns_ = 0;
};

}  // namespace needle::haptics
