// A time plot drawn with ImGui's draw list (Debian's ImGui has no implot): axes with ticks and
// labels in the plot's unit, the steps' start times, guide lines (limits, bands), the replay
// cursor, and optionally a second session's lines over the first for comparison.
#pragma once

#include <optional>
#include <vector>

#include "training/scoring/score.hpp"
#include "training/sessions/session_series.hpp"
#include "ui/time_span.hpp"

namespace needle::ui {

struct PlotOptions {
  float height = 140.0f;
  // The height holds the legend's rows past its first too (a legend that wraps, as a class's
  // learning curves' does, takes them from the plot), so the whole stays in the room given.
  bool fit_legend = false;
  std::optional<double> cursor_s;                            // the replay's time
  const std::vector<training::StepResult>* steps = nullptr;  // their start times, as dashed lines
  const training::Plot* other = nullptr;                     // session B's lines, drawn over (comparison)
  // The time range shown, y scaled to what lies in it; over the plot the wheel zooms it about the
  // pointer, a drag pans it and a double click shows the whole plot again. Null: the whole plot.
  TimeSpan* span = nullptr;
  // Learning curves (a line per trainee, a point per attempt): a look of its own (ui::trainee_style:
  // colour, dash and mark) for each of up to 24 lines, and every point marked, so a single attempt
  // shows too.
  bool marked_points = false;
};

void draw_plot(const training::Plot& plot, const PlotOptions& options = {});

}  // namespace needle::ui
