#include "ui/guidance_overlay.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>

#include "engine/screen_projection.hpp"
#include "training/tasks/condition.hpp"
#include "ui/guidance_colours.hpp"

namespace needle::ui {
namespace {

using training::operator*;  // the task geometry's plain-array arithmetic
using training::operator+;
using training::operator-;

const ImU32 kNow = IM_COL32(255, 255, 255, 255);
const ImU32 kNormal = IM_COL32(230, 110, 255, 255);
const ImU32 kLandmark = IM_COL32(255, 200, 60, 255);

// How far the planned axis is drawn behind its origin and ahead along its direction.
constexpr double kAxisBehind_m = 0.03;
constexpr double kAxisAhead_m = 0.08;

class Painter {
 public:
  explicit Painter(const GuidanceView& v)
      : camera_(v.camera),
        extent_{uint32_t(ImGui::GetIO().DisplaySize.x), uint32_t(ImGui::GetIO().DisplaySize.y)},
        list_(ImGui::GetBackgroundDrawList()) {}

  void line(const training::Vec3& a, const training::Vec3& b, ImU32 colour, float thickness) {
    const auto pa = to_screen(a), pb = to_screen(b);
    if (pa && pb) list_->AddLine(*pa, *pb, colour, thickness);
  }
  // A ring with its label to the right, or to the left (entry and target may share a point).
  void ring(const training::Vec3& p, ImU32 colour, float radius, const char* label, bool label_left = false) {
    if (const auto s = to_screen(p)) {
      list_->AddCircle(*s, radius, colour, 24, 2.0f);
      const float width = ImGui::CalcTextSize(label).x;
      text(ImVec2(label_left ? s->x - radius - 3.0f - width : s->x + radius + 3.0f, s->y - 7.0f), colour, label);
    }
  }
  void dot(const training::Vec3& p, ImU32 colour, float radius) {
    if (const auto s = to_screen(p)) list_->AddCircleFilled(*s, radius, colour, 16);
  }
  void cross(const training::Vec3& p, ImU32 colour, float half) {
    if (const auto s = to_screen(p)) {
      list_->AddLine(ImVec2(s->x - half, s->y - half), ImVec2(s->x + half, s->y + half), colour, 2.0f);
      list_->AddLine(ImVec2(s->x - half, s->y + half), ImVec2(s->x + half, s->y - half), colour, 2.0f);
    }
  }
  // A tick across the screen image of the line a-b, at a, `half` pixels to each side, its label
  // beyond the tick's end on the right of the screen, or on the left.
  void tick(const training::Vec3& a, const training::Vec3& b, ImU32 colour, const char* label, float half = 9.0f,
            bool label_left = false) {
    const auto pa = to_screen(a), pb = to_screen(b);
    if (!pa || !pb) return;
    const float dx = pb->x - pa->x, dy = pb->y - pa->y, length = std::hypot(dx, dy);
    if (length < 1e-3f) return;
    const ImVec2 across(-dy / length * half, dx / length * half);
    list_->AddLine(ImVec2(pa->x - across.x, pa->y - across.y), ImVec2(pa->x + across.x, pa->y + across.y), colour,
                   2.0f);
    const float side = (across.x >= 0.0f) == label_left ? -1.0f : 1.0f;  // the tick's end on the label's side
    const ImVec2 end(pa->x + side * across.x, pa->y + side * across.y);
    if (!label_left) {
      text(ImVec2(end.x + 4.0f, end.y - 7.0f), colour, label);
      return;
    }
    // Marks a few pixels apart (skin 2 mm thick) would print over each other: each left label
    // goes at least a line below the one before (the marks come in order of depth).
    const float y = std::max(end.y - 7.0f, left_label_next_y_);
    left_label_next_y_ = y + ImGui::GetTextLineHeight();
    text(ImVec2(end.x - 4.0f - ImGui::CalcTextSize(label).x, y), colour, label);
  }

 private:
  std::optional<ImVec2> to_screen(const training::Vec3& p) const {
    const auto s = engine::project_to_screen(camera_, extent_, glm::vec3(p[0], p[1], p[2]));
    if (!s) return std::nullopt;
    return ImVec2(s->x, s->y);
  }
  // Labels over tissue of any colour: a dark shadow under the text.
  void text(ImVec2 at, ImU32 colour, const char* label) {
    list_->AddText(ImVec2(at.x + 1.0f, at.y + 1.0f), IM_COL32(0, 0, 0, 200), label);
    list_->AddText(at, colour, label);
  }

  const engine::Camera& camera_;
  engine::Extent extent_;
  ImDrawList* list_;
  float left_label_next_y_ = -1e9f;
};

void draw_axis(Painter& paint, const training::Task& task, const training::Marker& marker, const training::Vec3& tip) {
  if (marker.kind == training::MarkerKind::kAxis) {
    paint.line(marker.position - kAxisBehind_m * marker.direction, marker.position + kAxisAhead_m * marker.direction,
               kAxisColour, 2.0f);
    paint.dot(marker.position, kAxisColour, 3.0f);
    return;
  }
  // A surface normal: the line through the three normal markers, down to the surface.
  const std::array<training::Vec3, 3> out = normal_marker_positions(task, marker, tip);
  paint.line(out[0] - (out[1] - out[0]), out[2], kAxisColour, 2.0f);
}

// The gauge along its axis: the condition's band, where each layer begins (its name unless the task
// hides them: the marks stay, unnamed), the tip's depth.
void draw_depth_gauge(Painter& paint, const training::Task& task, int marker, const training::Condition& band,
                      const training::Vec3& tip) {
  const training::Marker& axis = task.markers[size_t(marker)];
  paint.line(axis.position + band.min * axis.direction, axis.position + band.max * axis.direction, kBandColour, 7.0f);
  const auto at = [&](double depth) { return axis.position + depth * axis.direction; };
  char label[96];
  static const std::vector<training::LayerStart> kNone;  // a task built in code may leave layer_starts empty
  for (const training::LayerStart& s :
       size_t(marker) < task.layer_starts.size() ? task.layer_starts[size_t(marker)] : kNone) {
    if (s.layer < 0 || s.depth_m < -kAxisBehind_m || s.depth_m > kAxisAhead_m)
      continue;                                                            // out of the tissue, off the drawn axis
    const double mm = std::abs(s.depth_m) < 5e-4 ? 0.0 : s.depth_m * 1e3;  // no "-0 mm" at the skin
    if (task.hide_layer_names)
      std::snprintf(label, sizeof label, "%.0f mm", mm);
    else
      std::snprintf(label, sizeof label, "%s %.0f mm", task.layers[size_t(s.layer)].name.c_str(), mm);
    paint.tick(at(s.depth_m), at(s.depth_m + 0.01), kLayerStartColour, label, 6.0f, true);
  }
  const double depth = depth_along(axis, tip);
  std::snprintf(label, sizeof label, "depth %.0f mm (%.0f-%.0f)", depth * 1e3, band.min * 1e3, band.max * 1e3);
  paint.tick(at(depth), at(depth + 0.01), kNow, label);
}

// A patient's landmarks: Tuffier's line between the iliac crests' tops (drawn 3 cm beyond each),
// and each spinous process's tip with its level.
void draw_landmarks(Painter& paint, const training::PatientLandmarks& l) {
  const training::Vec3 across = l.crest_tops[1] - l.crest_tops[0];
  const double beyond = 0.03 / training::norm(across);
  const training::Vec3 a = l.crest_tops[0] - beyond * across, b = l.crest_tops[1] + beyond * across;
  paint.line(a, b, kLandmark, 2.0f);
  paint.ring(b, kLandmark, 4.0f, "Tuffier's line");
  static constexpr const char* kLevels[] = {"L1", "L2", "L3", "L4", "L5", "S1"};
  for (size_t i = 0; i < l.spinous_tips.size(); ++i) paint.ring(l.spinous_tips[i], kLandmark, 5.0f, kLevels[i]);
}

}  // namespace

training::ViewAxes view_axes(const engine::Camera& camera) {
  const glm::dvec3 forward = glm::normalize(glm::dvec3(camera.target - camera.position));
  const glm::dvec3 right = glm::normalize(glm::cross(forward, glm::dvec3(camera.up)));
  const glm::dvec3 up = glm::cross(right, forward);
  return {{right.x, right.y, right.z}, {up.x, up.y, up.z}, {forward.x, forward.y, forward.z}};
}

void draw_guidance(const GuidanceView& view) {
  const training::Task& task = *view.task;
  const training::Step& step = task.steps.at(view.step);
  const training::Guidance& g = step.guidance;
  Painter paint(view);
  if (g.axis >= 0) draw_axis(paint, task, task.markers[g.axis], view.tip);
  const bool gauge = g.depth_gauge >= 0 && step.condition.type == training::ConditionType::kDepthInBand;
  if (gauge) draw_depth_gauge(paint, task, g.depth_gauge, step.condition, view.tip);
  if (g.entry >= 0) paint.ring(task.markers[g.entry].position, kEntryColour, 9.0f, "entry", true);
  if (g.target >= 0) {
    // With a gauge, the target's label gives its depth along the gauge's axis.
    const training::Vec3& target = task.markers[g.target].position;
    char label[48] = "target";
    if (gauge)
      std::snprintf(label, sizeof label, "target %.0f mm", depth_along(task.markers[g.depth_gauge], target) * 1e3);
    paint.ring(target, kTargetColour, 9.0f, label);
    paint.cross(target, kTargetColour, 4.0f);
  }
  if (g.landmarks && task.landmarks) draw_landmarks(paint, *task.landmarks);
  if (g.normal_markers >= 0) {
    for (const training::Vec3& p : normal_marker_positions(task, task.markers[g.normal_markers], view.tip))
      paint.dot(p, kNormal, 5.0f);
  }
}

}  // namespace needle::ui
