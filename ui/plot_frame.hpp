// What every plot of the review draws alike with ImGui's draw list (Debian's ImGui has no implot):
// the rectangle at the cursor, the data-to-pixel mapping, the grid with y and x ticks and their
// labels, and the legend below. Used by the time plots (ui/review_plot.hpp) and the force–depth
// plot (ui/force_depth_plot.hpp).
#pragma once

#include <imgui.h>

#include <cstddef>
#include <string>
#include <utility>
#include <vector>

namespace needle::ui {

// Session A's lines in blues and greens, session B's in oranges, in the order of their lines.
inline const ImU32 kPlotLinesA[] = {IM_COL32(110, 190, 255, 255), IM_COL32(120, 220, 140, 255)};
inline const ImU32 kPlotLinesB[] = {IM_COL32(255, 160, 70, 255), IM_COL32(240, 90, 120, 255)};
inline const ImU32 kPlotAxis = IM_COL32(150, 150, 160, 255), kPlotGrid = IM_COL32(70, 70, 80, 255),
                   kPlotText = IM_COL32(200, 200, 205, 255), kPlotGuide = IM_COL32(255, 220, 80, 200),
                   kPlotStep = IM_COL32(120, 120, 135, 255);

struct PlotFrame {
  ImVec2 origin;  // the cursor where the plot began
  ImVec2 p0, p1;  // the data rectangle, top left and bottom right
  float width = 0.0f, height = 0.0f;
  double x_lo = 0.0, x_hi = 1.0, y_lo = 0.0, y_hi = 1.0;
  float sx(double x) const { return float(p0.x + (x - x_lo) / (x_hi - x_lo) * (p1.x - p0.x)); }
  float sy(double y) const { return float(p1.y - (y - y_lo) / (y_hi - y_lo) * (p1.y - p0.y)); }
};

// (x range, y range of the data, the plot's height) => the frame at the cursor, the full width
// available; y gets 5 % of its span above (and below when it goes negative), an empty range 1.
PlotFrame plot_frame(double x_lo, double x_hi, double y_lo, double y_hi, float height);

// A piece of text a plot draws, where: its top left corner and its size (ImGui's text size).
struct PlotLabel {
  std::string text;
  ImVec2 at, size;
  bool overlaps(const PlotLabel& o) const {
    return at.x < o.at.x + o.size.x && o.at.x < at.x + size.x && at.y < o.at.y + o.size.y && o.at.y < at.y + size.y;
  }
};

// The frame's labels: each y tick's left of the plot, each x tick's under it (whole numbers only
// when `whole_x`), and `x_label` at the right end of the tick row (a tick label it would cover is
// left out). None overlaps another, none leaves the frame (the rectangle from its origin, its width
// and height). Needs ImGui's current font.
std::vector<PlotLabel> plot_frame_labels(const PlotFrame& frame, const std::string& x_label, bool whole_x = false);

// The background, the grid and the ticks, and plot_frame_labels.
void draw_plot_frame(ImDrawList* draw, const PlotFrame& frame, const std::string& x_label, bool whole_x = false);

// Labels of vertical lines at pixel x `at_x` (the force–depth plot's layers), in the plot's rows
// from its top: each beside its line, on the right, or on the left where it would pass the plot's
// right edge, in the first row where it overlaps no label before it. A label no row has room for is
// left out (its line stays); none overlaps another or leaves the plot.
std::vector<PlotLabel> line_labels(const PlotFrame& frame, const std::vector<float>& at_x,
                                   const std::vector<std::string>& texts);

// A label of a point of the plot (a puncture): its text, where the point is, the label's colour.
struct PointLabel {
  std::string text;
  ImVec2 point;
  ImU32 colour;
};
// Where each point's label goes: up and right of its point (left of it at the plot's right edge),
// moved down a line at a time until it overlaps none of `taken` or of the labels before it, inside
// the plot; with the label's colour. A label with no room is left out (its point stays marked).
std::vector<std::pair<PlotLabel, ImU32>> point_labels(const PlotFrame& frame, const std::vector<PointLabel>& points,
                                                      const std::vector<PlotLabel>& taken);

// A dashed vertical line from top to bottom at x (pixels).
void dashed_vertical(ImDrawList* draw, float x, float top, float bottom, ImU32 colour);

// How a line looks: its colour, its dash and the mark drawn at each of its points (kNone: none).
enum class Dash { kSolid, kDashed, kDotted };
enum class Mark { kNone, kCircle, kSquare, kTriangle };
struct LineStyle {
  ImU32 colour = kPlotLinesA[0];
  Dash dash = Dash::kSolid;
  Mark mark = Mark::kNone;
};

// Learning curves: line k's style, one of kTraineeStyles that differ pairwise (eight hues far
// enough apart on the dark plot, each solid with circles, dashed with squares, dotted with
// triangles), so that no two of up to 24 trainees look alike; from the 25th they repeat.
inline constexpr size_t kTraineeStyles = 24;
LineStyle trainee_style(size_t k);
// Line k of one session's plot in the session's two colours (kPlotLinesA or kPlotLinesB): the first
// two solid, the next two dashed, then dotted, so no two lines of a plot look alike.
LineStyle session_line_style(const ImU32 (&colours)[2], size_t k);

// The polyline through `points` in `style`'s colour and dash, and its mark at each point.
void draw_styled_line(ImDrawList* draw, const std::vector<ImVec2>& points, const LineStyle& style, float width);
void draw_mark(ImDrawList* draw, ImVec2 at, const LineStyle& style);

// (each legend entry's width, the width there is, the gap between entries) => the row of each
// entry, filled left to right: an entry goes on the next row when it would pass the width (one
// wider than the width has a row of its own). Every entry gets a place.
std::vector<int> legend_rows(const std::vector<float>& widths, float width, float gap);

// A legend entry: a swatch of the line (a filled square for a plain line, else a piece of the line
// with its mark) and the line's name.
using LegendEntry = std::pair<std::string, LineStyle>;
// The rows the legend of `entries` takes in the width there is at the cursor (legend_rows).
int plot_legend_rows(const std::vector<LegendEntry>& entries);

// Ends the plot (its space taken) and draws the legend below it, wrapped onto as many rows as it
// needs (plot_legend_rows): every line named.
void draw_plot_legend(const PlotFrame& frame, const std::vector<LegendEntry>& entries);

}  // namespace needle::ui
