#include "ui/probe_overlay.hpp"

#include <imgui.h>

#include <array>
#include <optional>

#include "engine/screen_projection.hpp"

namespace needle::ui {
namespace {

const ImU32 kFace = IM_COL32(120, 230, 255, 255);
const ImU32 kPlaneFill = IM_COL32(120, 230, 255, 60);
const ImU32 kPlaneEdge = IM_COL32(120, 230, 255, 200);

}  // namespace

void draw_probe(const engine::UltrasoundProbe& probe, const engine::Camera& camera) {
  const ImGuiIO& io = ImGui::GetIO();
  const engine::Extent extent{uint32_t(io.DisplaySize.x), uint32_t(io.DisplaySize.y)};
  const auto screen = [&](const glm::dvec3& p) -> std::optional<ImVec2> {
    const auto s = engine::project_to_screen(camera, extent, glm::vec3(p));
    if (!s) return std::nullopt;
    return ImVec2(s->x, s->y);
  };
  const glm::dvec3 half_width = 0.5 * probe.width_m * probe.lateral;
  const glm::dvec3 half_face = 0.5 * kProbeFaceThickness_m * probe.elevation();
  const glm::dvec3 depth = probe.depth_m * probe.direction;
  // The imaged plane: the face's centre line down to the imaging depth.
  const std::array<std::optional<ImVec2>, 4> plane{
      screen(probe.position - half_width), screen(probe.position + half_width),
      screen(probe.position + half_width + depth), screen(probe.position - half_width + depth)};
  // The face: the array's width by the housing's thickness, on the skin.
  const std::array<std::optional<ImVec2>, 4> face{
      screen(probe.position - half_width - half_face), screen(probe.position + half_width - half_face),
      screen(probe.position + half_width + half_face), screen(probe.position - half_width + half_face)};
  ImDrawList* list = ImGui::GetBackgroundDrawList();
  const auto quad = [&](const std::array<std::optional<ImVec2>, 4>& q, ImU32 fill, ImU32 edge, float thickness) {
    for (const auto& p : q)
      if (!p) return;  // a corner behind the camera: not drawn
    if (fill) list->AddQuadFilled(*q[0], *q[1], *q[2], *q[3], fill);
    list->AddQuad(*q[0], *q[1], *q[2], *q[3], edge, thickness);
  };
  quad(plane, kPlaneFill, kPlaneEdge, 1.5f);
  quad(face, 0, kFace, 2.5f);
}

}  // namespace needle::ui
