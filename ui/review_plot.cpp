#include "ui/review_plot.hpp"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>

namespace needle::ui {
namespace {

// Session A's lines in blues and greens, session B's in oranges, in the order of Plot::lines.
const ImU32 kLinesA[] = {IM_COL32(110, 190, 255, 255), IM_COL32(120, 220, 140, 255)};
const ImU32 kLinesB[] = {IM_COL32(255, 160, 70, 255), IM_COL32(240, 90, 120, 255)};
const ImU32 kAxis = IM_COL32(150, 150, 160, 255), kGrid = IM_COL32(70, 70, 80, 255), kText = IM_COL32(200, 200, 205, 255);
const ImU32 kGuide = IM_COL32(255, 220, 80, 200), kStep = IM_COL32(120, 120, 135, 255), kCursor = IM_COL32(255, 255, 255, 230);

struct Range {
  double lo = std::numeric_limits<double>::infinity(), hi = -std::numeric_limits<double>::infinity();
  void add(double v) {
    if (!std::isfinite(v)) return;
    lo = std::min(lo, v);
    hi = std::max(hi, v);
  }
};

std::string number(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", std::abs(v) < 1e-12 ? 0.0 : v);
  return text;
}

// The samples of `s` inside [span.lo, span.hi], with one more on either side so that the line
// runs to the plot's edges.
training::Series visible(const training::Series& s, const TimeSpan& span) {
  const auto first = std::lower_bound(s.t.begin(), s.t.end(), span.lo);
  const auto last = std::upper_bound(first, s.t.end(), span.hi);
  const size_t i0 = size_t(std::max<std::ptrdiff_t>(first - s.t.begin() - 1, 0));
  const size_t i1 = std::min(size_t(last - s.t.begin()) + 1, s.t.size());
  return {s.name, {s.t.begin() + std::ptrdiff_t(i0), s.t.begin() + std::ptrdiff_t(i1)},
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
  if (ImGui::IsItemActive() && io.MouseDelta.x != 0.0f) span = panned(shown, whole, -double(io.MouseDelta.x) * seconds_per_pixel);
  if (ImGui::IsItemHovered() && ImGui::IsMouseDoubleClicked(ImGuiMouseButton_Left)) span = {};
  ImGui::SetCursorScreenPos(back);
}

void dashed_vertical(ImDrawList* draw, float x, float top, float bottom, ImU32 colour) {
  for (float y = top; y < bottom; y += 6.0f) draw->AddLine(ImVec2(x, y), ImVec2(x, std::min(y + 3.0f, bottom)), colour);
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
  std::vector<std::pair<const training::Series*, ImU32>> lines;
  for (size_t i = 0; i < plot.lines.size(); ++i) lines.push_back({&plot.lines[i], kLinesA[i % 2]});
  if (o.other) {
    for (size_t i = 0; i < o.other->lines.size(); ++i) lines.push_back({&o.other->lines[i], kLinesB[i % 2]});
  }
  Range x, y;
  for (const auto& [series, colour] : lines) {
    for (double t : series->t) x.add(t);
  }
  if (!(x.hi > x.lo)) x.hi = x.lo + 1.0;
  const TimeSpan whole{x.lo, x.hi}, shown = o.span ? clamped(*o.span, whole) : whole;
  x.lo = shown.lo;
  x.hi = shown.hi;
  std::vector<std::pair<training::Series, ImU32>> in_span;
  y.add(0.0);  // every plotted quantity is read from zero
  for (const auto& [series, colour] : lines) {
    in_span.push_back({visible(*series, shown), colour});
    for (size_t i = 0; i < in_span.back().first.t.size(); ++i) {
      const double t = in_span.back().first.t[i];
      if (t >= shown.lo && t <= shown.hi) y.add(in_span.back().first.v[i]);
    }
  }
  // Zoomed in, y fits the lines alone (a limit far above them would flatten what the zoom is for).
  if (shown.width() >= whole.width()) {
    for (const training::Guide& g : plot.guides) y.add(g.value);
  }
  if (!(y.hi > y.lo)) y.hi = y.lo + 1.0;
  const double pad = 0.05 * (y.hi - y.lo);
  y.lo -= y.lo < 0.0 ? pad : 0.0;
  y.hi += pad;

  const float left = 52.0f, bottom = 18.0f, right = 8.0f;
  const ImVec2 origin = ImGui::GetCursorScreenPos();
  const float width = ImGui::GetContentRegionAvail().x;
  const ImVec2 p0(origin.x + left, origin.y + 4.0f), p1(origin.x + width - right, origin.y + o.height - bottom);
  auto sx = [&](double t) { return float(p0.x + (t - x.lo) / (x.hi - x.lo) * (p1.x - p0.x)); };
  auto sy = [&](double v) { return float(p1.y - (v - y.lo) / (y.hi - y.lo) * (p1.y - p0.y)); };
  if (o.span) zoom_and_pan(plot, *o.span, shown, whole, p0, p1);
  ImDrawList* draw = ImGui::GetWindowDrawList();
  draw->AddRectFilled(p0, p1, IM_COL32(22, 22, 28, 255));
  for (double v : training::axis_ticks(y.lo, y.hi, 4)) {
    draw->AddLine(ImVec2(p0.x, sy(v)), ImVec2(p1.x, sy(v)), kGrid);
    const std::string label = number(v);
    draw->AddText(ImVec2(p0.x - 6.0f - ImGui::CalcTextSize(label.c_str()).x, sy(v) - 7.0f), kText, label.c_str());
  }
  for (double t : training::axis_ticks(x.lo, x.hi, 8)) {
    draw->AddLine(ImVec2(sx(t), p1.y), ImVec2(sx(t), p1.y + 4.0f), kAxis);
    const std::string label = number(t);
    draw->AddText(ImVec2(sx(t) - 0.5f * ImGui::CalcTextSize(label.c_str()).x, p1.y + 3.0f), kText, label.c_str());
  }
  draw->AddText(ImVec2(origin.x + 4.0f, p1.y + 3.0f), kText, plot.x_label.c_str());
  draw->PushClipRect(p0, p1, true);
  if (o.steps) {
    for (size_t k = 0; k < o.steps->size(); ++k) {
      const double start = (*o.steps)[k].record.start_s;
      if (!std::isfinite(start)) continue;
      dashed_vertical(draw, sx(start), p0.y, p1.y, kStep);
      draw->AddText(ImVec2(sx(start) + 2.0f, p0.y), kStep, std::to_string(k + 1).c_str());
    }
  }
  for (const training::Guide& g : plot.guides) {
    draw->AddLine(ImVec2(p0.x, sy(g.value)), ImVec2(p1.x, sy(g.value)), kGuide);
    const ImVec2 size = ImGui::CalcTextSize(g.label.c_str());
    const float above = sy(g.value) - size.y;  // below the line when it runs along the top
    draw->AddText(ImVec2(p1.x - size.x - 2.0f, above < p0.y ? sy(g.value) + 1.0f : above), kGuide, g.label.c_str());
  }
  std::vector<ImVec2> points;
  for (const auto& [series, colour] : in_span) {
    const training::Series drawn = decimate(series, size_t(std::max(1.0f, p1.x - p0.x)));
    points.clear();
    for (size_t i = 0; i < drawn.t.size(); ++i) {
      if (std::isfinite(drawn.v[i])) points.push_back(ImVec2(sx(drawn.t[i]), sy(drawn.v[i])));
    }
    if (points.size() > 1) draw->AddPolyline(points.data(), int(points.size()), colour, 0, 1.5f);
  }
  if (o.cursor_s) draw->AddLine(ImVec2(sx(*o.cursor_s), p0.y), ImVec2(sx(*o.cursor_s), p1.y), kCursor, 1.5f);
  draw->PopClipRect();
  draw->AddRect(p0, p1, kAxis);
  ImGui::Dummy(ImVec2(width, o.height));
  // Legend: one swatch and name per line; session B's marked as such.
  for (size_t i = 0; i < lines.size(); ++i) {
    if (i > 0) ImGui::SameLine();
    const ImVec2 at = ImGui::GetCursorScreenPos();
    draw->AddRectFilled(ImVec2(at.x, at.y + 4.0f), ImVec2(at.x + 10.0f, at.y + 12.0f), lines[i].second);
    ImGui::Dummy(ImVec2(12.0f, 12.0f));
    ImGui::SameLine();
    const bool b = i >= plot.lines.size();
    ImGui::Text("%s%s", lines[i].first->name.c_str(), b ? " (B)" : o.other ? " (A)" : "");
  }
}

}  // namespace needle::ui
