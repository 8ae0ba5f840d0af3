// How the haptic loop kept time over a recorded session, from each sample's measured
// period: an instructor sees when a session's haptics were degraded (a window that starved the
// loop, a busy machine). Offline runs (`run --headless`) tick unpaced and record the nominal
// period, so they read as on time.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "haptics/realtime/tick_sample.hpp"

namespace needle::training {

struct LoopHealth {
  uint64_t ticks = 0;
  double nominal_hz = 0.0;
  double rate_hz = 0.0;  // ticks / the sum of their periods
  double period_p99_ms = 0.0;
  double period_max_ms = 0.0;
  uint64_t late_ticks = 0;  // periods longer than kLatePeriods nominal ones

  // Degraded: the rate 5 % under nominal, or more than 1 % of the ticks late (design values: the
  // device then holds a command for two periods or more often enough to matter to the feel).
  bool degraded() const;
};

// A tick is late when its period exceeds this many nominal periods (design value: at 1 kHz a 2 ms
// hold, one missed update).
inline constexpr double kLatePeriods = 2.0;

// (the recorded samples, the loop's nominal rate) => the loop's health over them.
LoopHealth loop_health(const std::vector<haptics::TickSample>& samples, double nominal_hz);

// One line for the review and the report: "haptic loop 999.8 Hz (nominal 1000), period p99 1.07 ms,
// worst 6.59 ms, 3 late ticks of 53999", with ": degraded" at the end when it was.
std::string describe(const LoopHealth& health);

}  // namespace needle::training
