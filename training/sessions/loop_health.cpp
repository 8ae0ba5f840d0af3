#include "training/sessions/loop_health.hpp"

#include <algorithm>
#include <cstdio>

namespace needle::training {

bool LoopHealth::degraded() const {
  return ticks > 0 && (rate_hz < 0.95 * nominal_hz || double(late_ticks) > 0.01 * double(ticks));
}

LoopHealth loop_health(const std::vector<haptics::TickSample>& samples, double nominal_hz) {
  LoopHealth h;
  h.nominal_hz = nominal_hz;
  // The first sample's period is the nominal one or the wait for the loop's start: left out.
  if (samples.size() < 2) return h;
  std::vector<uint64_t> periods;
  periods.reserve(samples.size() - 1);
  for (size_t k = 1; k < samples.size(); ++k) periods.push_back(samples[k].period_ns);
  h.ticks = periods.size();
  double total_ns = 0.0;
  const double late_ns = kLatePeriods * 1e9 / nominal_hz;
  for (uint64_t p : periods) {
    total_ns += double(p);
    h.late_ticks += double(p) > late_ns;
  }
  h.rate_hz = total_ns > 0.0 ? double(h.ticks) / (total_ns * 1e-9) : 0.0;
  const auto p99 = periods.begin() + std::ptrdiff_t(0.99 * double(periods.size() - 1));
  std::nth_element(periods.begin(), p99, periods.end());
  h.period_p99_ms = double(*p99) * 1e-6;
  h.period_max_ms = double(*std::max_element(periods.begin(), periods.end())) * 1e-6;
  return h;
}

std::string describe(const LoopHealth& h) {
  char line[200];
  std::snprintf(line, sizeof line,
                "haptic loop %.1f Hz (nominal %g), period p99 %.2f ms, worst %.2f ms, %llu late ticks of %llu%s",
                h.rate_hz, h.nominal_hz, h.period_p99_ms, h.period_max_ms,
                static_cast<unsigned long long>(h.late_ticks), static_cast<unsigned long long>(h.ticks),
                h.degraded() ? ": degraded" : "");
  return line;
}

}  // namespace needle::training
