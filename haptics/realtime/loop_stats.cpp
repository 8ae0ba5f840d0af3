#include "haptics/realtime/loop_stats.hpp"

namespace needle::haptics {

void LoopStats::record(uint64_t period_ns, uint64_t nominal_ns, uint64_t compute_ns, bool overrun) noexcept {
  period_error_.record(period_ns > nominal_ns ? period_ns - nominal_ns : nominal_ns - period_ns);
  compute_.record(compute_ns);
  if (overrun) overruns_.store(overruns_.load(std::memory_order_relaxed) + 1, std::memory_order_relaxed);
  // Exponential mean over about 256 periods: the "current rate".
  const double mean = mean_period_ns_.load(std::memory_order_relaxed);
  const double p = static_cast<double>(period_ns);
  mean_period_ns_.store(mean == 0.0 ? p : mean + (p - mean) / 256.0, std::memory_order_relaxed);
  ticks_.store(ticks_.load(std::memory_order_relaxed) + 1, std::memory_order_release);
}

void LoopStats::clear() noexcept {
  period_error_.clear();
  compute_.clear();
  overruns_.store(0, std::memory_order_relaxed);
  mean_period_ns_.store(0.0, std::memory_order_relaxed);
}

LoopStatsSummary LoopStats::summary() const noexcept {
  LoopStatsSummary s;
  s.ticks = ticks_.load(std::memory_order_acquire);
  s.overruns = overruns_.load(std::memory_order_relaxed);
  const double mean = mean_period_ns_.load(std::memory_order_relaxed);
  s.rate_hz = mean > 0.0 ? 1e9 / mean : 0.0;
  s.nominal_rate_hz = nominal_rate_hz_.load(std::memory_order_relaxed);
  s.period_error = period_error_.summary();
  s.compute = compute_.summary();
  s.samples_dropped = dropped_.load(std::memory_order_relaxed);
  s.fault = fault_.load(std::memory_order_relaxed);
  return s;
}

}  // namespace needle::haptics
