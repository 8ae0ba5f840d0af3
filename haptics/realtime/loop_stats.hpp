// Timing of the haptic loop, written by the loop thread and readable from any thread
// without locks.
#pragma once

#include <atomic>
#include <cstdint>

#include "haptics/realtime/latency_histogram.hpp"

namespace needle::haptics {

struct LoopStatsSummary {
  uint64_t ticks = 0;
  uint64_t overruns = 0;
  double rate_hz = 0.0;  // measured over the recent periods
  double nominal_rate_hz = 0.0;
  LatencySummary period_error;   // |period - nominal period|
  LatencySummary compute;        // read + step + safety + write
  uint64_t samples_dropped = 0;  // sample ring overflow
  uint32_t fault = 0;            // FaultCause
};

class LoopStats {
 public:
  // Loop thread only.
  void record(uint64_t period_ns, uint64_t nominal_ns, uint64_t compute_ns, bool overrun) noexcept;
  void set_nominal_rate(double hz) noexcept { nominal_rate_hz_.store(hz, std::memory_order_relaxed); }
  void set_fault(uint32_t cause) noexcept { fault_.store(cause, std::memory_order_relaxed); }
  void set_samples_dropped(uint64_t n) noexcept { dropped_.store(n, std::memory_order_relaxed); }
  void clear() noexcept;

  // Any thread.
  LoopStatsSummary summary() const noexcept;
  uint64_t ticks() const noexcept { return ticks_.load(std::memory_order_acquire); }

 private:
  LatencyHistogram period_error_;
  LatencyHistogram compute_;
  std::atomic<uint64_t> ticks_{0};
  std::atomic<uint64_t> overruns_{0};
  std::atomic<double> mean_period_ns_{0.0};
  std::atomic<double> nominal_rate_hz_{0.0};
  std::atomic<uint32_t> fault_{0};
  std::atomic<uint64_t> dropped_{0};
};

}  // namespace needle::haptics
