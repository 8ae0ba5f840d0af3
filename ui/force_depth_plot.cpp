#include "ui/force_depth_plot.hpp"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

#include "ui/plot_frame.hpp"

namespace needle::ui {
namespace {

const ImU32 kPunctureA = IM_COL32(255, 80, 80, 255), kPunctureB = IM_COL32(255, 200, 60, 255);

// The lines and puncture marks of one session in its colours; its punctures' labels added to `labels`.
void draw_session(ImDrawList* draw, const PlotFrame& f, const training::ForceDepth& s, const ImU32 (&colours)[2],
                  ImU32 puncture, std::vector<PointLabel>& labels) {
  std::vector<ImVec2> points;
  for (size_t k = 0; k < s.plot.lines.size(); ++k) {
    const training::Series& line = s.plot.lines[k];
    points.clear();
    for (size_t i = 0; i < line.t.size(); ++i) points.push_back(ImVec2(f.sx(line.t[i]), f.sy(line.v[i])));
    if (points.size() > 1) draw->AddPolyline(points.data(), int(points.size()), colours[k % 2], 0, 1.5f);
  }
  for (const training::PlotMark& p : s.punctures) {
    const ImVec2 at(f.sx(p.x), f.sy(p.y));
    draw->AddCircle(at, 5.0f, puncture, 12, 2.0f);
    labels.push_back({p.label, at, puncture});
  }
}

}  // namespace

void draw_force_depth_plot(const training::ForceDepth& a, const training::ForceDepth* b, float height) {
  ImGui::Text("%s (%s)", a.plot.title.c_str(), a.plot.unit.c_str());
  const bool b_lines = b && !b->plot.lines.empty();
  if (a.plot.lines.empty() && !b_lines) {
    ImGui::TextColored(ImVec4(0.95f, 0.7f, 0.3f, 1.0f), "no plot:");
    ImGui::SameLine();
    ImGui::TextWrapped("%s", a.plot.missing.c_str());
    return;
  }
  double x_lo = 0.0, x_hi = -std::numeric_limits<double>::infinity(), y_lo = 0.0, y_hi = 0.0;  // read from zero
  for (const training::ForceDepth* s : {&a, b}) {
    if (!s) continue;
    for (const training::Series& line : s->plot.lines)
      for (size_t i = 0; i < line.t.size(); ++i) {
        x_lo = std::min(x_lo, line.t[i]), x_hi = std::max(x_hi, line.t[i]);
        y_lo = std::min(y_lo, line.v[i]), y_hi = std::max(y_hi, line.v[i]);
      }
  }
  if (!(x_hi > x_lo)) x_hi = x_lo + 1.0;
  const PlotFrame f = plot_frame(x_lo, x_hi, y_lo, y_hi, height);
  ImDrawList* draw = ImGui::GetWindowDrawList();
  draw_plot_frame(draw, f, a.plot.x_label);
  draw->PushClipRect(f.p0, f.p1, true);
  // The layer boundaries are the first session's: both ran the same task. Their names where they
  // overlap no other (layers a few millimetres apart would write over each other) and stay inside.
  std::vector<float> xs;
  std::vector<std::string> names;
  for (const training::PlotMark& m : a.boundaries) {
    dashed_vertical(draw, f.sx(m.x), f.p0.y, f.p1.y, kPlotStep);
    xs.push_back(f.sx(m.x));
    names.push_back(m.label);
  }
  const std::vector<PlotLabel> layers = line_labels(f, xs, names);
  for (const PlotLabel& l : layers) draw->AddText(l.at, kPlotText, l.text.c_str());
  std::vector<PointLabel> punctures;
  draw_session(draw, f, a, kPlotLinesA, kPunctureA, punctures);
  if (b) draw_session(draw, f, *b, kPlotLinesB, kPunctureB, punctures);
  for (const auto& [l, colour] : point_labels(f, punctures, layers)) draw->AddText(l.at, colour, l.text.c_str());
  draw->PopClipRect();
  std::vector<LegendEntry> legend{{b ? "force along the needle (A)" : "force along the needle", {kPlotLinesA[0]}},
                                  {b ? "punctures (A)" : "punctures", {kPunctureA}}};
  if (b) legend.insert(legend.end(), {{"force along the needle (B)", {kPlotLinesB[0]}}, {"punctures (B)", {kPunctureB}}});
  draw_plot_legend(f, legend);
}

}  // namespace needle::ui
