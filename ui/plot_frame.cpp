#include "ui/plot_frame.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iterator>

#include "training/sessions/session_series.hpp"

namespace needle::ui {
namespace {

std::string number(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", std::abs(v) < 1e-12 ? 0.0 : v);
  return text;
}

}  // namespace

PlotFrame plot_frame(double x_lo, double x_hi, double y_lo, double y_hi, float height) {
  PlotFrame f;
  f.x_lo = x_lo;
  f.x_hi = x_hi;
  if (!(y_hi > y_lo)) y_hi = y_lo + 1.0;
  const double pad = 0.05 * (y_hi - y_lo);
  f.y_lo = y_lo - (y_lo < 0.0 ? pad : 0.0);
  f.y_hi = y_hi + pad;
  const float left = 52.0f, bottom = 18.0f, right = 8.0f;
  f.origin = ImGui::GetCursorScreenPos();
  f.width = ImGui::GetContentRegionAvail().x;
  f.height = height;
  f.p0 = ImVec2(f.origin.x + left, f.origin.y + 4.0f);
  f.p1 = ImVec2(f.origin.x + f.width - right, f.origin.y + height - bottom);
  return f;
}

void draw_plot_frame(ImDrawList* draw, const PlotFrame& f, const std::string& x_label, bool whole_x) {
  draw->AddRectFilled(f.p0, f.p1, IM_COL32(22, 22, 28, 255));
  for (double v : training::axis_ticks(f.y_lo, f.y_hi, 4)) {
    draw->AddLine(ImVec2(f.p0.x, f.sy(v)), ImVec2(f.p1.x, f.sy(v)), kPlotGrid);
    const std::string label = number(v);
    draw->AddText(ImVec2(f.p0.x - 6.0f - ImGui::CalcTextSize(label.c_str()).x, f.sy(v) - 7.0f), kPlotText, label.c_str());
  }
  for (double t : training::axis_ticks(f.x_lo, f.x_hi, 8)) {
    if (whole_x && t != std::round(t)) continue;
    draw->AddLine(ImVec2(f.sx(t), f.p1.y), ImVec2(f.sx(t), f.p1.y + 4.0f), kPlotAxis);
    const std::string label = number(t);
    draw->AddText(ImVec2(f.sx(t) - 0.5f * ImGui::CalcTextSize(label.c_str()).x, f.p1.y + 3.0f), kPlotText, label.c_str());
  }
  draw->AddText(ImVec2(f.origin.x + 4.0f, f.p1.y + 3.0f), kPlotText, x_label.c_str());
}

void dashed_vertical(ImDrawList* draw, float x, float top, float bottom, ImU32 colour) {
  for (float y = top; y < bottom; y += 6.0f) draw->AddLine(ImVec2(x, y), ImVec2(x, std::min(y + 3.0f, bottom)), colour);
}

LineStyle trainee_style(size_t k) {
  // Eight hues far enough apart to tell trainees apart on the dark plot.
  static const ImU32 kHues[] = {IM_COL32(110, 190, 255, 255), IM_COL32(255, 160, 70, 255), IM_COL32(120, 220, 140, 255),
                                IM_COL32(240, 90, 120, 255),  IM_COL32(200, 150, 255, 255), IM_COL32(240, 230, 90, 255),
                                IM_COL32(90, 220, 220, 255),  IM_COL32(200, 200, 200, 255)};
  constexpr size_t hues = std::size(kHues);
  static_assert(hues * 3 == kTraineeStyles);
  const size_t style = (k / hues) % 3;
  return {kHues[k % hues], style == 0 ? Dash::kSolid : style == 1 ? Dash::kDashed : Dash::kDotted,
          style == 0 ? Mark::kCircle : style == 1 ? Mark::kSquare : Mark::kTriangle};
}

LineStyle session_line_style(const ImU32 (&colours)[2], size_t k) {
  const size_t dash = (k / 2) % 3;
  return {colours[k % 2], dash == 0 ? Dash::kSolid : dash == 1 ? Dash::kDashed : Dash::kDotted, Mark::kNone};
}

void draw_styled_line(ImDrawList* draw, const std::vector<ImVec2>& points, const LineStyle& style, float width) {
  if (style.dash == Dash::kSolid) {
    if (points.size() > 1) draw->AddPolyline(points.data(), int(points.size()), style.colour, 0, width);
  } else {
    // On and off lengths (pixels) walked along the line, the pattern carried over its corners.
    const float on = style.dash == Dash::kDashed ? 8.0f : 2.0f, off = style.dash == Dash::kDashed ? 5.0f : 4.0f;
    float phase = 0.0f;  // how far into the current on + off period
    for (size_t i = 1; i < points.size(); ++i) {
      const ImVec2 a = points[i - 1], b = points[i];
      const float length = std::hypot(b.x - a.x, b.y - a.y);
      for (float s = 0.0f; s < length;) {
        const bool drawing = phase < on;
        const float step = std::min(length - s, drawing ? on - phase : on + off - phase);
        if (drawing) {
          const float t0 = s / length, t1 = (s + step) / length;
          draw->AddLine(ImVec2(a.x + (b.x - a.x) * t0, a.y + (b.y - a.y) * t0), ImVec2(a.x + (b.x - a.x) * t1, a.y + (b.y - a.y) * t1),
                        style.colour, width);
        }
        s += step;
        phase = std::fmod(phase + step, on + off);
      }
    }
  }
  for (const ImVec2& p : points) draw_mark(draw, p, style);
}

void draw_mark(ImDrawList* draw, ImVec2 at, const LineStyle& style) {
  const float r = 3.5f;
  switch (style.mark) {
    case Mark::kNone: return;
    case Mark::kCircle: return draw->AddCircleFilled(at, r, style.colour);
    case Mark::kSquare: return draw->AddRectFilled(ImVec2(at.x - r, at.y - r), ImVec2(at.x + r, at.y + r), style.colour);
    case Mark::kTriangle:
      return draw->AddTriangleFilled(ImVec2(at.x, at.y - r - 0.5f), ImVec2(at.x + r + 0.5f, at.y + r), ImVec2(at.x - r - 0.5f, at.y + r),
                                     style.colour);
  }
}

std::vector<int> legend_rows(const std::vector<float>& widths, float width, float gap) {
  std::vector<int> rows;
  int row = 0;
  float x = 0.0f;
  for (const float w : widths) {
    if (x > 0.0f && x + gap + w > width) ++row, x = 0.0f;
    x += (x > 0.0f ? gap : 0.0f) + w;
    rows.push_back(row);
  }
  return rows;
}

namespace {

// A legend swatch: a plain line's filled square, or a piece of a styled line with its mark.
constexpr float kSquareSwatch = 12.0f, kLineSwatch = 26.0f;

float swatch_width(const LineStyle& s) { return s.dash == Dash::kSolid && s.mark == Mark::kNone ? kSquareSwatch : kLineSwatch; }

// Each entry's width as drawn: the swatch, ImGui's spacing, the name.
std::vector<float> entry_widths(const std::vector<LegendEntry>& entries) {
  std::vector<float> widths;
  for (const auto& [name, style] : entries)
    widths.push_back(swatch_width(style) + ImGui::GetStyle().ItemSpacing.x + ImGui::CalcTextSize(name.c_str()).x);
  return widths;
}

}  // namespace

int plot_legend_rows(const std::vector<LegendEntry>& entries) {
  if (entries.empty()) return 0;
  return legend_rows(entry_widths(entries), ImGui::GetContentRegionAvail().x, ImGui::GetStyle().ItemSpacing.x).back() + 1;
}

void draw_plot_legend(const PlotFrame& f, const std::vector<LegendEntry>& entries) {
  ImDrawList* draw = ImGui::GetWindowDrawList();
  draw->AddRect(f.p0, f.p1, kPlotAxis);
  ImGui::Dummy(ImVec2(f.width, f.height));
  const std::vector<int> rows = legend_rows(entry_widths(entries), ImGui::GetContentRegionAvail().x, ImGui::GetStyle().ItemSpacing.x);
  for (size_t i = 0; i < entries.size(); ++i) {
    if (i > 0 && rows[i] == rows[i - 1]) ImGui::SameLine();
    const ImVec2 at = ImGui::GetCursorScreenPos();
    const LineStyle& style = entries[i].second;
    const float w = swatch_width(style);
    if (w == kSquareSwatch) {
      draw->AddRectFilled(ImVec2(at.x, at.y + 4.0f), ImVec2(at.x + 10.0f, at.y + 12.0f), style.colour);
    } else {
      const float y = at.y + 8.0f;
      draw_styled_line(draw, {ImVec2(at.x, y), ImVec2(at.x + w - 2.0f, y)}, LineStyle{style.colour, style.dash, Mark::kNone}, 1.5f);
      draw_mark(draw, ImVec2(at.x + 0.5f * (w - 2.0f), y), style);
    }
    ImGui::Dummy(ImVec2(w, 12.0f));
    ImGui::SameLine();
    ImGui::Text("%s", entries[i].first.c_str());
  }
}

}  // namespace needle::ui
