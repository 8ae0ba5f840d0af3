#include "ui/plot_frame.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

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

void draw_plot_legend(const PlotFrame& f, const std::vector<std::pair<std::string, ImU32>>& entries) {
  ImDrawList* draw = ImGui::GetWindowDrawList();
  draw->AddRect(f.p0, f.p1, kPlotAxis);
  ImGui::Dummy(ImVec2(f.width, f.height));
  for (size_t i = 0; i < entries.size(); ++i) {
    if (i > 0) ImGui::SameLine();
    const ImVec2 at = ImGui::GetCursorScreenPos();
    draw->AddRectFilled(ImVec2(at.x, at.y + 4.0f), ImVec2(at.x + 10.0f, at.y + 12.0f), entries[i].second);
    ImGui::Dummy(ImVec2(12.0f, 12.0f));
    ImGui::SameLine();
    ImGui::Text("%s", entries[i].first.c_str());
  }
}

}  // namespace needle::ui
