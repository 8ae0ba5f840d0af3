#include "ui/time_span.hpp"

#include <algorithm>

namespace needle::ui {

TimeSpan clamped(TimeSpan s, const TimeSpan& whole) {
  if (!s.chosen()) return whole;
  const double width = std::min(std::max(s.width(), kMinSpanS), whole.width());
  const double centre = 0.5 * (s.lo + s.hi);
  s.lo = std::clamp(centre - 0.5 * width, whole.lo, whole.hi - width);
  s.hi = s.lo + width;
  return s;
}

TimeSpan zoomed(const TimeSpan& span, const TimeSpan& whole, double t, double factor) {
  const TimeSpan s = clamped(span, whole);
  return clamped({t - (t - s.lo) * factor, t + (s.hi - t) * factor}, whole);
}

TimeSpan panned(const TimeSpan& span, const TimeSpan& whole, double by_s) {
  const TimeSpan s = clamped(span, whole);
  return clamped({s.lo + by_s, s.hi + by_s}, whole);
}

}  // namespace needle::ui
