// The time range the review's plots show, so that an instructor can zoom into a second of a
// minute-long session (a 6 Hz wobble is a solid band at 800 pixels for 54 s, and lines at 2 s).
// Pure arithmetic, no ImGui: the plot calls it from the wheel and the drag, the report from
// --from/--to.
#pragma once

namespace needle::ui {

struct TimeSpan {
  double lo = 0.0, hi = 0.0;  // s; hi <= lo: not chosen yet, the whole session is shown
  bool chosen() const { return hi > lo; }
  double width() const { return hi - lo; }
};

// The narrowest span shown: 50 ticks of the 1 kHz loop, a few periods of anything above 50 Hz
// still drawn with a sample per pixel or more (design value).
inline constexpr double kMinSpanS = 0.05;

// (span, whole) => the span moved inside `whole` with its width kept (cut to whole's when wider)
// and widened about its centre to kMinSpanS; an unchosen span is `whole`.
TimeSpan clamped(TimeSpan span, const TimeSpan& whole);

// (span, whole, t, factor) => the span scaled by `factor` (< 1 zooms in) about the time t, which
// keeps its place on the axis: lo' = t - (t - lo)·factor, hi' = t + (hi - t)·factor; then clamped.
TimeSpan zoomed(const TimeSpan& span, const TimeSpan& whole, double about_s, double factor);

// (span, whole, dt) => the span moved later by dt seconds (earlier when negative); then clamped.
TimeSpan panned(const TimeSpan& span, const TimeSpan& whole, double by_s);

}  // namespace needle::ui
