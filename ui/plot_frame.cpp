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

namespace {

PlotLabel label_at(const std::string& text, float x, float y) {
  return {text, ImVec2(x, y), ImGui::CalcTextSize(text.c_str())};
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
  // Room for the y tick labels and the x tick row, in the font's size (13 px text: 52 and 18 px).
  const float em = ImGui::GetFontSize();
  const float left = 4.0f * em, bottom = 1.4f * em, right = 8.0f;
  f.origin = ImGui::GetCursorScreenPos();
  f.width = ImGui::GetContentRegionAvail().x;
  f.height = height;
  f.p0 = ImVec2(f.origin.x + left, f.origin.y + 4.0f);
  f.p1 = ImVec2(f.origin.x + f.width - right, f.origin.y + height - bottom);
  return f;
}

std::vector<PlotLabel> plot_frame_labels(const PlotFrame& f, const std::string& x_label, bool whole_x) {
  std::vector<PlotLabel> out;
  const float half_line = 0.5f * ImGui::GetFontSize();
  for (double v : training::axis_ticks(f.y_lo, f.y_hi, 4)) {
    const std::string text = number(v);
    const float w = ImGui::CalcTextSize(text.c_str()).x;
    // Centred on its grid line, kept inside the frame at the top and above the x tick row.
    const float y = std::clamp(f.sy(v) - half_line, f.origin.y, f.p1.y - 2.0f * half_line);
    PlotLabel label = label_at(text, std::max(f.origin.x, f.p0.x - 6.0f - w), y);
    if (out.empty() || !label.overlaps(out.back())) out.push_back(label);
  }
  const size_t y_labels = out.size();
  const PlotLabel axis = label_at(x_label, 0.0f, f.p1.y + 3.0f);
  const PlotLabel named{x_label, ImVec2(f.origin.x + f.width - axis.size.x, f.p1.y + 3.0f), axis.size};
  for (double t : training::axis_ticks(f.x_lo, f.x_hi, 8)) {
    if (whole_x && t != std::round(t)) continue;
    const std::string text = number(t);
    const float w = ImGui::CalcTextSize(text.c_str()).x;
    const float x = std::clamp(f.sx(t) - 0.5f * w, f.origin.x, f.origin.x + f.width - w);
    const PlotLabel label = label_at(text, x, f.p1.y + 3.0f);
    if (!x_label.empty() && label.overlaps(named)) continue;
    if (out.size() > y_labels && label.overlaps(out.back())) continue;
    bool clear = true;
    for (size_t k = 0; k < y_labels; ++k) clear = clear && !label.overlaps(out[k]);
    if (clear) out.push_back(label);
  }
  if (!x_label.empty()) out.push_back(named);
  return out;
}

void draw_plot_frame(ImDrawList* draw, const PlotFrame& f, const std::string& x_label, bool whole_x) {
  draw->AddRectFilled(f.p0, f.p1, IM_COL32(22, 22, 28, 255));
  for (double v : training::axis_ticks(f.y_lo, f.y_hi, 4))
    draw->AddLine(ImVec2(f.p0.x, f.sy(v)), ImVec2(f.p1.x, f.sy(v)), kPlotGrid);
  for (double t : training::axis_ticks(f.x_lo, f.x_hi, 8)) {
    if (whole_x && t != std::round(t)) continue;
    draw->AddLine(ImVec2(f.sx(t), f.p1.y), ImVec2(f.sx(t), f.p1.y + 4.0f), kPlotAxis);
  }
  for (const PlotLabel& l : plot_frame_labels(f, x_label, whole_x)) draw->AddText(l.at, kPlotText, l.text.c_str());
}

std::vector<std::pair<PlotLabel, ImU32>> point_labels(const PlotFrame& f, const std::vector<PointLabel>& points,
                                                      const std::vector<PlotLabel>& taken) {
  const float line = ImGui::GetTextLineHeight();
  std::vector<PlotLabel> placed = taken;
  std::vector<std::pair<PlotLabel, ImU32>> out;
  for (const PointLabel& p : points) {
    const float w = ImGui::CalcTextSize(p.text.c_str()).x;
    const float x = p.point.x + 6.0f + w <= f.p1.x ? p.point.x + 6.0f : std::max(f.p0.x, p.point.x - 6.0f - w);
    for (float y = std::max(f.p0.y, p.point.y - line - 1.0f); y + line <= f.p1.y; y += line) {
      const PlotLabel label = label_at(p.text, x, y);
      bool clear = true;
      for (const PlotLabel& other : placed) clear = clear && !label.overlaps(other);
      if (!clear) continue;
      placed.push_back(label);
      out.push_back({label, p.colour});
      break;
    }
  }
  return out;
}

std::vector<PlotLabel> line_labels(const PlotFrame& f, const std::vector<float>& at_x,
                                   const std::vector<std::string>& texts) {
  const float line = ImGui::GetTextLineHeight();
  const int rows = std::max(1, int((f.p1.y - f.p0.y) / line));
  std::vector<std::vector<PlotLabel>> placed(static_cast<size_t>(rows));
  std::vector<PlotLabel> out;
  for (size_t k = 0; k < at_x.size() && k < texts.size(); ++k) {
    const float w = ImGui::CalcTextSize(texts[k].c_str()).x;
    const float x = at_x[k] + 2.0f + w <= f.p1.x ? at_x[k] + 2.0f : std::max(f.p0.x, at_x[k] - 2.0f - w);
    for (int r = 0; r < rows; ++r) {
      const PlotLabel label = label_at(texts[k], x, f.p0.y + float(r) * line);
      bool clear = true;
      for (const PlotLabel& other : placed[size_t(r)]) clear = clear && !label.overlaps(other);
      if (!clear) continue;
      placed[size_t(r)].push_back(label);
      out.push_back(label);
      break;
    }
  }
  return out;
}

void dashed_vertical(ImDrawList* draw, float x, float top, float bottom, ImU32 colour) {
  for (float y = top; y < bottom; y += 6.0f) draw->AddLine(ImVec2(x, y), ImVec2(x, std::min(y + 3.0f, bottom)), colour);
}

LineStyle trainee_style(size_t k) {
  // Eight hues far enough apart to tell trainees apart on the dark plot.
  static const ImU32 kHues[] = {IM_COL32(110, 190, 255, 255), IM_COL32(255, 160, 70, 255),
                                IM_COL32(120, 220, 140, 255), IM_COL32(240, 90, 120, 255),
                                IM_COL32(200, 150, 255, 255), IM_COL32(240, 230, 90, 255),
                                IM_COL32(90, 220, 220, 255),  IM_COL32(200, 200, 200, 255)};
  constexpr size_t hues = std::size(kHues);
  static_assert(hues * 3 == kTraineeStyles);
  const size_t style = (k / hues) % 3;
  return {kHues[k % hues],
          style == 0   ? Dash::kSolid
          : style == 1 ? Dash::kDashed
                       : Dash::kDotted,
          style == 0   ? Mark::kCircle
          : style == 1 ? Mark::kSquare
                       : Mark::kTriangle};
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
          draw->AddLine(ImVec2(a.x + (b.x - a.x) * t0, a.y + (b.y - a.y) * t0),
                        ImVec2(a.x + (b.x - a.x) * t1, a.y + (b.y - a.y) * t1), style.colour, width);
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
    case Mark::kNone:
      return;
    case Mark::kCircle:
      return draw->AddCircleFilled(at, r, style.colour);
    case Mark::kSquare:
      return draw->AddRectFilled(ImVec2(at.x - r, at.y - r), ImVec2(at.x + r, at.y + r), style.colour);
    case Mark::kTriangle:
      return draw->AddTriangleFilled(ImVec2(at.x, at.y - r - 0.5f), ImVec2(at.x + r + 0.5f, at.y + r),
                                     ImVec2(at.x - r - 0.5f, at.y + r), style.colour);
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

float swatch_width(const LineStyle& s) {
  return s.dash == Dash::kSolid && s.mark == Mark::kNone ? kSquareSwatch : kLineSwatch;
}

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
  return legend_rows(entry_widths(entries), ImGui::GetContentRegionAvail().x, ImGui::GetStyle().ItemSpacing.x).back() +
         1;
}

void draw_plot_legend(const PlotFrame& f, const std::vector<LegendEntry>& entries) {
  ImDrawList* draw = ImGui::GetWindowDrawList();
  draw->AddRect(f.p0, f.p1, kPlotAxis);
  ImGui::Dummy(ImVec2(f.width, f.height));
  const std::vector<int> rows =
      legend_rows(entry_widths(entries), ImGui::GetContentRegionAvail().x, ImGui::GetStyle().ItemSpacing.x);
  for (size_t i = 0; i < entries.size(); ++i) {
    if (i > 0 && rows[i] == rows[i - 1]) ImGui::SameLine();
    const ImVec2 at = ImGui::GetCursorScreenPos();
    const LineStyle& style = entries[i].second;
    const float w = swatch_width(style);
    if (w == kSquareSwatch) {
      draw->AddRectFilled(ImVec2(at.x, at.y + 4.0f), ImVec2(at.x + 10.0f, at.y + 12.0f), style.colour);
    } else {
      const float y = at.y + 8.0f;
      draw_styled_line(draw, {ImVec2(at.x, y), ImVec2(at.x + w - 2.0f, y)},
                       LineStyle{style.colour, style.dash, Mark::kNone}, 1.5f);
      draw_mark(draw, ImVec2(at.x + 0.5f * (w - 2.0f), y), style);
    }
    ImGui::Dummy(ImVec2(w, 12.0f));
    ImGui::SameLine();
    ImGui::Text("%s", entries[i].first.c_str());
  }
}

}  // namespace needle::ui
