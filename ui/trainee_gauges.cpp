#include "ui/trainee_gauges.hpp"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "ui/guidance_colours.hpp"
#include "ui/wrapped_text.hpp"

namespace needle::ui {
namespace {

const ImVec4 kBadText(0.9f, 0.3f, 0.25f, 1.0f), kWarnText(0.95f, 0.6f, 0.2f, 1.0f), kPlainText(1.0f, 1.0f, 1.0f, 1.0f);
const ImU32 kTrack = IM_COL32(40, 40, 46, 255);

// A bar over the panel's width: x_of maps a reading onto it.
struct Bar {
  ImVec2 origin;
  float width, height;
  ImDrawList* draw;
};

Bar begin_bar() {
  Bar b{ImGui::GetCursorScreenPos(), ImGui::GetContentRegionAvail().x, 14.0f * ImGui::GetFontSize() / 13.0f,
        ImGui::GetWindowDrawList()};
  b.draw->AddRectFilled(b.origin, ImVec2(b.origin.x + b.width, b.origin.y + b.height), kTrack);
  return b;
}
void end_bar(const Bar& b) { ImGui::Dummy(ImVec2(b.width, b.height)); }

float x_at(const Bar& b, double value, double lo, double hi) {
  return b.origin.x + float(std::clamp((value - lo) / (hi - lo), 0.0, 1.0)) * b.width;
}

// A fill from lo to `value`, inset, and a tick across the bar at `at`.
void fill(const Bar& b, double from, double to, double lo, double hi, ImU32 colour, float inset = 3.0f) {
  b.draw->AddRectFilled(ImVec2(x_at(b, from, lo, hi), b.origin.y + inset),
                        ImVec2(x_at(b, to, lo, hi), b.origin.y + b.height - inset), colour);
}
void tick(const Bar& b, double at, double lo, double hi, ImU32 colour, float thickness = 2.0f) {
  const float x = x_at(b, at, lo, hi);
  b.draw->AddLine(ImVec2(x, b.origin.y), ImVec2(x, b.origin.y + b.height), colour, thickness);
}

}  // namespace

void countdown_gauge(double left_s, double limit_s) {
  left_s = std::clamp(left_s, 0.0, limit_s);
  const Bar b = begin_bar();
  const ImU32 colour = left_s <= kCountdownDanger_s ? IM_COL32(220, 70, 60, 255)
                       : left_s <= kCountdownWarn_s ? IM_COL32(240, 150, 40, 255)
                                                    : IM_COL32(150, 150, 170, 255);
  fill(b, 0.0, left_s, 0.0, limit_s, colour);
  end_bar(b);
  if (left_s <= kCountdownWarn_s)
    wrapped_text(left_s <= kCountdownDanger_s ? kBadText : kWarnText, "%.0f s left of %.0f s", std::ceil(left_s),
                 limit_s);
  else
    wrapped_text(kPlainText, "%.0f s left of %.0f s", std::ceil(left_s), limit_s);
}

void force_gauge(double force, double safe, double band_min, double band_max) {
  const double full = std::max({safe * 1.5, band_max * 1.2, 1e-6});
  const Bar b = begin_bar();
  fill(b, 0.0, safe, 0.0, full, IM_COL32(40, 80, 50, 255), 0.0f);
  const bool over = force > safe;
  fill(b, 0.0, force, 0.0, full, over ? IM_COL32(220, 70, 60, 255) : IM_COL32(120, 200, 255, 255));
  if (band_max > band_min)
    b.draw->AddRect(ImVec2(x_at(b, band_min, 0.0, full), b.origin.y),
                    ImVec2(x_at(b, band_max, 0.0, full), b.origin.y + b.height), IM_COL32(255, 220, 80, 255), 0.0f, 0,
                    2.0f);
  end_bar(b);
  if (over)
    wrapped_text(kBadText, "force at the hand %.2f N: OVER the safe %.1f N", force, safe);
  else
    wrapped_text(kPlainText, "force at the hand %.2f N   safe < %.1f N", force, safe);
}

void sideways_gauge(double sideways, double safe) {
  const double full = safe * 1.5;
  const double warn = kSidewaysWarnShare * safe, danger = kSidewaysDangerShare * safe;
  const Bar b = begin_bar();
  const ImU32 colour = sideways >= danger ? IM_COL32(220, 70, 60, 255)
                       : sideways >= warn ? IM_COL32(240, 150, 40, 255)
                                          : IM_COL32(120, 200, 255, 255);
  fill(b, 0.0, sideways, 0.0, full, colour);
  tick(b, warn, 0.0, full, IM_COL32(240, 150, 40, 255));
  end_bar(b);
  if (sideways >= danger)
    wrapped_text(kBadText, "sideways on the needle %.2f N: you are bending it", sideways);
  else if (sideways >= warn)
    wrapped_text(kWarnText, "sideways on the needle %.2f N: ease off sideways", sideways);
  else
    wrapped_text(kPlainText, "sideways on the needle %.2f N", sideways);
}

void distance_gauge(const training::Task& task, size_t step, const training::StepCue& cue) {
  if (cue.point < 0) return;
  constexpr double kFull_m = 0.05;
  const Bar b = begin_bar();
  fill(b, 0.0, cue.distance_m, 0.0, kFull_m, kEntryColour);
  tick(b, task.steps[step].condition.within_m, 0.0, kFull_m, IM_COL32(255, 255, 255, 255));
  end_bar(b);
  wrapped_text(kPlainText, "to the %s %.1f mm (within %.0f mm)",
               cue.point == task.steps[step].guidance.target ? "target" : "point", cue.distance_m * 1000.0,
               task.steps[step].condition.within_m * 1000.0);
}

void axis_gauge(const training::StepCue& cue) {
  if (cue.axis < 0) return;
  constexpr double kFull_deg = 45.0;
  const Bar b = begin_bar();
  fill(b, 0.0, cue.off_axis_deg, 0.0, kFull_deg, kAxisColour);
  if (!std::isnan(cue.within_deg)) tick(b, cue.within_deg, 0.0, kFull_deg, IM_COL32(255, 255, 255, 255));
  end_bar(b);
  if (std::isnan(cue.within_deg))
    wrapped_text(kPlainText, "off the planned axis %.0f deg", cue.off_axis_deg);
  else
    wrapped_text(kPlainText, "off the planned axis %.0f deg (within %.0f)", cue.off_axis_deg, cue.within_deg);
}

PadPoint turn_pad_point(double turn_deg, double tilt_deg) {
  const double angle = std::hypot(turn_deg, tilt_deg);
  if (!(angle > 0.0)) return {};
  const double reach = std::sqrt(std::min(angle, kTurnPadFull_deg) / kTurnPadFull_deg);
  return {reach * turn_deg / angle, reach * tilt_deg / angle};
}

void turn_pad(const training::StepCue& cue) {
  if (cue.axis < 0 || std::isnan(cue.off_axis_deg)) return;
  const float unit = ImGui::GetFontSize() / 13.0f, side = 52.0f * unit, dot = 4.0f * unit;
  const ImVec2 corner = ImGui::GetCursorScreenPos();
  const ImVec2 centre(corner.x + 0.5f * side, corner.y + 0.5f * side);
  const float reach = 0.5f * side - dot - 2.0f * unit;  // the dot stays inside the frame
  ImDrawList* draw = ImGui::GetWindowDrawList();
  draw->AddRectFilled(corner, ImVec2(corner.x + side, corner.y + side), kTrack);
  const ImU32 cross = IM_COL32(90, 90, 100, 255);
  draw->AddLine(ImVec2(centre.x, corner.y), ImVec2(centre.x, corner.y + side), cross);
  draw->AddLine(ImVec2(corner.x, centre.y), ImVec2(corner.x + side, centre.y), cross);
  draw->AddRect(corner, ImVec2(corner.x + side, corner.y + side), kAxisColour);
  if (!std::isnan(cue.within_deg))
    draw->AddCircle(centre, reach * float(turn_pad_point(cue.within_deg, 0.0).x), IM_COL32(255, 255, 255, 255), 0,
                    1.5f * unit);
  const PadPoint p = turn_pad_point(cue.turn_deg, cue.tilt_deg);
  const ImVec2 at(centre.x + reach * float(p.x), centre.y - reach * float(p.y));  // up on the screen is y down
  draw->AddLine(centre, at, kAxisColour, 2.0f * unit);
  draw->AddCircleFilled(at, dot, kAxisColour);
  ImGui::Dummy(ImVec2(side, side));
  ImGui::SameLine();
  ImGui::BeginGroup();
  wrapped_text(kPlainText, "turn the wrist towards the dot: right is clockwise as seen, up the hub away");
  ImGui::EndGroup();
}

void depth_gauge(const training::Task& task, size_t step, const training::StepCue& cue) {
  if (cue.gauge < 0) return;
  const training::Step& s = task.steps[step];
  double deepest = 0.04;
  if (!std::isnan(cue.band_max_m)) deepest = std::max(deepest, cue.band_max_m);
  if (s.guidance.target >= 0 && task.markers[size_t(cue.gauge)].kind == training::MarkerKind::kAxis)
    deepest = std::max(deepest, training::gauge_depth(task.markers[size_t(cue.gauge)],
                                                      task.markers[size_t(s.guidance.target)].position));
  const double lo = -0.01, hi = deepest + 0.01;
  const Bar b = begin_bar();
  if (!std::isnan(cue.band_min_m)) fill(b, cue.band_min_m, cue.band_max_m, lo, hi, kBandColour, 0.0f);
  if (size_t(cue.gauge) < task.layer_starts.size())
    for (const training::LayerStart& start : task.layer_starts[size_t(cue.gauge)])
      if (start.layer >= 0 && start.depth_m > lo && start.depth_m < hi)
        tick(b, start.depth_m, lo, hi, kLayerStartColour, 1.0f);
  tick(b, 0.0, lo, hi, IM_COL32(150, 150, 160, 255), 1.0f);  // the surface, or the axis's origin
  tick(b, cue.depth_m, lo, hi, IM_COL32(255, 255, 255, 255), 3.0f);
  end_bar(b);
  const double mm = cue.depth_m * 1000.0;
  if (!std::isnan(cue.band_min_m))
    wrapped_text(kPlainText, "depth %.0f mm   band %.0f-%.0f mm", mm, cue.band_min_m * 1000.0, cue.band_max_m * 1000.0);
  else
    wrapped_text(kPlainText, "depth %.0f mm%s", mm,
                 mm >= 0 ? ""
                 : task.markers[size_t(cue.gauge)].kind == training::MarkerKind::kSurfaceNormal
                     ? " (above the surface)"
                     : " (before the planned path begins)");
}

}  // namespace needle::ui
