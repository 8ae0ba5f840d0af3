#include "ui/review_plot.hpp"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "ui/plot_frame.hpp"

namespace needle::ui {
namespace {

const ImU32 kCursor = IM_COL32(255, 255, 255, 230);

struct Range {
  double lo = std::numeric_limits<double>::infinity(), hi = -std::numeric_limits<double>::infinity();
  void add(double v) {
    if (!std::isfinite(v)) return;
    lo = std::min(lo, v);
    hi = std::max(hi, v);
  }
};

// The samples of `s` inside [span.lo, span.hi], with one more on either side so that the line
// runs to the plot's edges.
training::Series visible(const training::Series& s, const TimeSpan& span) {
  const auto first = std::lower_bound(s.t.begin(), s.t.end(), span.lo);
  const auto last = std::upper_bound(first, s.t.end(), span.hi);
  const size_t i0 = size_t(std::max<std::ptrdiff_t>(first - s.t.begin() - 1, 0));
  const size_t i1 = std::min(size_t(last - s.t.begin()) + 1, s.t.size());
  return {s.name,
          {s.t.begin() + std::ptrdiff_t(i0), s.t.begin() + std::ptrdiff_t(i1)},
          {s.v.begin() + std::ptrdiff_t(i0), s.v.begin() + std::ptrdiff_t(i1)}};
}

// The wheel, the drag and the double click over the plot's rectangle [p0, p1] => the next frame's span.
void zoom_and_pan(const training::Plot& plot, TimeSpan& span, const TimeSpan& shown, const TimeSpan& whole, ImVec2 p0,
                  ImVec2 p1) {
  const ImVec2 back = ImGui::GetCursorScreenPos();
  ImGui::SetCursorScreenPos(p0);
  ImGui::PushID(&plot);
  ImGui::InvisibleButton("##span", ImVec2(p1.x - p0.x, p1.y - p0.y));
  ImGui::PopID();
  const ImGuiIO& io = ImGui::GetIO();
  const double seconds_per_pixel = shown.width() / double(p1.x - p0.x);
  if (ImGui::IsItemHovered() && io.MouseWheel != 0.0f) {
    const double t = shown.lo + double(io.MousePos.x - p0.x) * seconds_per_pixel;
    span = zoomed(shown, whole, t, std::pow(0.8, double(io.MouseWheel)));  // a notch: a fifth narrower
  }
  if (ImGui::IsItemActive() && io.MouseDelta.x != 0.0f)
    span = panned(shown, whole, -double(io.MouseDelta.x) * seconds_per_pixel);
  if (ImGui::IsItemHovered() && ImGui::IsMouseDoubleClicked(ImGuiMouseButton_Left)) span = {};
  ImGui::SetCursorScreenPos(back);
}

}  // namespace

void draw_plot(const training::Plot& plot, const PlotOptions& o) {
  ImGui::Text("%s (%s)", plot.title.c_str(), plot.unit.c_str());
  if (plot.lines.empty() && (!o.other || o.other->lines.empty())) {
    ImGui::TextColored(ImVec4(0.95f, 0.7f, 0.3f, 1.0f), "no plot:");
    ImGui::SameLine();
    ImGui::TextWrapped("%s", plot.missing.c_str());
    return;
  }
  std::vector<std::pair<const training::Series*, LineStyle>> lines;
  for (size_t i = 0; i < plot.lines.size(); ++i)
    lines.push_back({&plot.lines[i], o.marked_points ? trainee_style(i) : session_line_style(kPlotLinesA, i)});
  if (o.other) {
    for (size_t i = 0; i < o.other->lines.size(); ++i)
      lines.push_back({&o.other->lines[i], session_line_style(kPlotLinesB, i)});
  }
  std::vector<LegendEntry> legend;
  for (size_t i = 0; i < lines.size(); ++i) {
    const bool b = i >= plot.lines.size();
    legend.push_back({lines[i].first->name + (b ? " (B)" : o.other ? " (A)" : ""), lines[i].second});
  }
  Range x, y;
  for (const auto& [series, style] : lines) {
    for (double t : series->t) x.add(t);
  }
  if (o.marked_points) x.lo -= 0.5, x.hi += 0.5;  // the first and last attempts' marks clear of the edges
  if (!(x.hi > x.lo)) x.hi = x.lo + 1.0;
  const TimeSpan whole{x.lo, x.hi}, shown = o.span ? clamped(*o.span, whole) : whole;
  x.lo = shown.lo;
  x.hi = shown.hi;
  std::vector<std::pair<training::Series, LineStyle>> in_span;
  y.add(0.0);  // every plotted quantity is read from zero
  for (const auto& [series, style] : lines) {
    in_span.push_back({visible(*series, shown), style});
    for (size_t i = 0; i < in_span.back().first.t.size(); ++i) {
      const double t = in_span.back().first.t[i];
      if (t >= shown.lo && t <= shown.hi) y.add(in_span.back().first.v[i]);
    }
  }
  // Zoomed in, y fits the lines alone (a limit far above them would flatten what the zoom is for).
  if (shown.width() >= whole.width()) {
    for (const training::Guide& g : plot.guides) y.add(g.value);
  }
  // The legend's rows past its first taken from the plot, when the height is the legend's too.
  const int more_rows = o.fit_legend ? std::max(0, plot_legend_rows(legend) - 1) : 0;
  const PlotFrame f =
      plot_frame(x.lo, x.hi, y.lo, y.hi, o.height - float(more_rows) * ImGui::GetTextLineHeightWithSpacing());
  const ImVec2 p0 = f.p0, p1 = f.p1;
  if (o.span) zoom_and_pan(plot, *o.span, shown, whole, p0, p1);
  ImDrawList* draw = ImGui::GetWindowDrawList();
  draw_plot_frame(draw, f, plot.x_label, o.marked_points);  // attempts are whole numbers
  draw->PushClipRect(p0, p1, true);
  if (o.steps) {
    for (size_t k = 0; k < o.steps->size(); ++k) {
      const double start = (*o.steps)[k].record.start_s;
      if (!std::isfinite(start)) continue;
      dashed_vertical(draw, f.sx(start), p0.y, p1.y, kPlotStep);
      draw->AddText(ImVec2(f.sx(start) + 2.0f, p0.y), kPlotStep, std::to_string(k + 1).c_str());
    }
  }
  for (const training::Guide& g : plot.guides) {
    draw->AddLine(ImVec2(p0.x, f.sy(g.value)), ImVec2(p1.x, f.sy(g.value)), kPlotGuide);
    const ImVec2 size = ImGui::CalcTextSize(g.label.c_str());
    const float above = f.sy(g.value) - size.y;  // below the line when it runs along the top
    draw->AddText(ImVec2(p1.x - size.x - 2.0f, above < p0.y ? f.sy(g.value) + 1.0f : above), kPlotGuide,
                  g.label.c_str());
  }
  std::vector<ImVec2> points;
  for (const auto& [series, style] : in_span) {
    const training::Series drawn = decimate(series, size_t(std::max(1.0f, p1.x - p0.x)));
    points.clear();
    for (size_t i = 0; i < drawn.t.size(); ++i) {
      if (std::isfinite(drawn.v[i])) points.push_back(ImVec2(f.sx(drawn.t[i]), f.sy(drawn.v[i])));
    }
    draw_styled_line(draw, points, style, 1.5f);
  }
  if (o.cursor_s) draw->AddLine(ImVec2(f.sx(*o.cursor_s), p0.y), ImVec2(f.sx(*o.cursor_s), p1.y), kCursor, 1.5f);
  draw->PopClipRect();
  draw_plot_legend(f, legend);
}

}  // namespace needle::ui
