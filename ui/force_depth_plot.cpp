#include "ui/force_depth_plot.hpp"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "ui/plot_frame.hpp"

namespace needle::ui {
namespace {

const ImU32 kPunctureA = IM_COL32(255, 80, 80, 255), kPunctureB = IM_COL32(255, 200, 60, 255);

// What a depth plot draws of one session: its lines and its marks (the punctures, or the losses).
struct DepthPlotPart {
  const training::Plot* plot;
  const std::vector<training::PlotMark>* marks;
};
using PartOf = DepthPlotPart (*)(const training::ForceDepth&);

// The lines and marks of one session in its colours; its marks' labels added to `labels`.
void draw_session(ImDrawList* draw, const PlotFrame& f, const DepthPlotPart& s, const ImU32 (&colours)[2], ImU32 mark,
                  std::vector<PointLabel>& labels) {
  std::vector<ImVec2> points;
  for (size_t k = 0; k < s.plot->lines.size(); ++k) {
    const training::Series& line = s.plot->lines[k];
    points.clear();
    for (size_t i = 0; i < line.t.size(); ++i) points.push_back(ImVec2(f.sx(line.t[i]), f.sy(line.v[i])));
    if (points.size() > 1) draw->AddPolyline(points.data(), int(points.size()), colours[k % 2], 0, 1.5f);
  }
  for (const training::PlotMark& p : *s.marks) {
    const ImVec2 at(f.sx(p.x), f.sy(p.y));
    draw->AddCircle(at, 5.0f, mark, 12, 2.0f);
    labels.push_back({p.label, at, mark});
  }
}

// A plot against depth of `part` of session a (and b), the layer boundaries a's, the legend naming
// the lines `line` and the marks `marks`.
void draw_depth_plot(const training::ForceDepth& a, const training::ForceDepth* b, float height, PartOf part,
                     const char* line, const char* marks) {
  const DepthPlotPart pa = part(a);
  ImGui::Text("%s (%s)", pa.plot->title.c_str(), pa.plot->unit.c_str());
  const bool b_lines = b && !part(*b).plot->lines.empty();
  if (pa.plot->lines.empty() && !b_lines) {
    ImGui::TextColored(ImVec4(0.95f, 0.7f, 0.3f, 1.0f), "no plot:");
    ImGui::SameLine();
    ImGui::TextWrapped("%s", pa.plot->missing.c_str());
    return;
  }
  double x_lo = 0.0, x_hi = -std::numeric_limits<double>::infinity(), y_lo = 0.0, y_hi = 0.0;  // read from zero
  for (const training::ForceDepth* s : {&a, b}) {
    if (!s) continue;
    for (const training::Series& l : part(*s).plot->lines)
      for (size_t i = 0; i < l.t.size(); ++i) {
        x_lo = std::min(x_lo, l.t[i]), x_hi = std::max(x_hi, l.t[i]);
        y_lo = std::min(y_lo, l.v[i]), y_hi = std::max(y_hi, l.v[i]);
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
  std::vector<PointLabel> labels;
  draw_session(draw, f, pa, kPlotLinesA, kPunctureA, labels);
  if (b) draw_session(draw, f, part(*b), kPlotLinesB, kPunctureB, labels);
  for (const auto& [l, colour] : point_labels(f, labels, layers)) draw->AddText(l.at, colour, l.text.c_str());
  draw->PopClipRect();
  const std::string l(line), m(marks);
  std::vector<LegendEntry> legend{{b ? l + " (A)" : l, {kPlotLinesA[0]}}, {b ? m + " (A)" : m, {kPunctureA}}};
  if (b) legend.insert(legend.end(), {{l + " (B)", {kPlotLinesB[0]}}, {m + " (B)", {kPunctureB}}});
  draw_plot_legend(f, legend);
}

}  // namespace

void draw_force_depth_plot(const training::ForceDepth& a, const training::ForceDepth* b, float height) {
  draw_depth_plot(
      a, b, height,
      [](const training::ForceDepth& s) {
        return DepthPlotPart{&s.plot, &s.punctures};
      },
      "force along the needle", "punctures");
}

void draw_plunger_pressure_plot(const training::ForceDepth& a, const training::ForceDepth* b, float height) {
  draw_depth_plot(
      a, b, height,
      [](const training::ForceDepth& s) {
        return DepthPlotPart{&s.pressure, &s.losses};
      },
      "plunger pressure", "losses of resistance");
}

}  // namespace needle::ui
