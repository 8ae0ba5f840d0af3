#include "ui/syringe_gauge.hpp"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>

#include "engine/screen_projection.hpp"

namespace needle::ui {
namespace {

using training::operator*;
using training::operator+;
using training::operator-;

// A loss-of-resistance syringe's proportions (design values, a 5 mL barrel): the nozzle 10 mm, the
// barrel 8.5 mm in radius, the stopper 4 mm thick, the rod's thumb rest 12 mm across.
constexpr double kNozzle_m = 0.010, kBarrelRadius_m = 0.0085, kStopper_m = 0.004, kRest_m = 0.012;
constexpr double kMmHgPerPa = 760.0 / 101325.0;

const ImU32 kBarrel = IM_COL32(235, 240, 245, 200);
const ImU32 kSaline = IM_COL32(90, 170, 255, 150);
const ImU32 kAir = IM_COL32(225, 235, 240, 70);
const ImU32 kStopperColour = IM_COL32(40, 40, 45, 255);
const ImU32 kRod = IM_COL32(245, 245, 245, 230);
const ImU32 kText = IM_COL32(255, 255, 255, 255);

class Projector {
 public:
  explicit Projector(const engine::Camera& camera)
      : camera_(camera), extent_{uint32_t(ImGui::GetIO().DisplaySize.x), uint32_t(ImGui::GetIO().DisplaySize.y)} {}
  std::optional<ImVec2> operator()(const training::Vec3& p) const {
    const auto s = engine::project_to_screen(camera_, extent_, glm::vec3(p[0], p[1], p[2]));
    if (!s) return std::nullopt;
    return ImVec2(s->x, s->y);
  }

 private:
  const engine::Camera& camera_;
  engine::Extent extent_;
};

}  // namespace

void draw_syringe_gauge(const SyringeGaugeView& v) {
  const haptics::SyringeSnapshot& y = v.syringe;
  if (y.fluid == 0) return;
  const Projector screen(v.camera);
  // Along the needle behind its hub: d is the distance behind the tip; `side` is across the needle as
  // seen (perpendicular to the needle and to the view), so the barrel's width reads the same from anywhere.
  const training::Vec3 view_dir{v.camera.target.x - v.camera.position.x, v.camera.target.y - v.camera.position.y,
                                v.camera.target.z - v.camera.position.z};
  training::Vec3 side = training::cross(v.axis, view_dir);
  if (training::norm(side) < 1e-9) side = training::cross(v.axis, training::Vec3{0.0, 0.0, 1.0});
  if (training::norm(side) < 1e-9) return;
  side = (1.0 / training::norm(side)) * side;
  const auto at = [&](double behind, double across) { return screen(v.tip - behind * v.axis + across * side); };
  ImDrawList* list = ImGui::GetBackgroundDrawList();
  const auto quad = [&](double from, double to, double half, ImU32 colour, bool filled) {
    const auto a = at(from, -half), b = at(from, half), c = at(to, half), d = at(to, -half);
    if (!a || !b || !c || !d) return;
    if (filled)
      list->AddQuadFilled(*a, *b, *c, *d, colour);
    else
      list->AddQuad(*a, *b, *c, *d, colour, 1.5f);
  };
  const double stroke = std::max(v.stroke_m, 1e-3), travel = std::clamp(y.travel_m, 0.0, stroke);
  const double nozzle = kHubBehindTip_m, barrel = nozzle + kNozzle_m, barrel_end = barrel + stroke + kStopper_m + 0.006;
  const double stopper =
      barrel + (stroke - travel);  // the stopper's face on the fluid: it moves in as the plunger travels
  quad(nozzle, barrel, 0.0025, kBarrel, true);
  quad(barrel, stopper, kBarrelRadius_m, y.fluid == 2 ? kAir : kSaline, true);
  quad(stopper, stopper + kStopper_m, kBarrelRadius_m, kStopperColour, true);
  quad(stopper + kStopper_m, stopper + kStopper_m + stroke + 0.012, 0.002, kRod, true);
  quad(stopper + kStopper_m + stroke + 0.012, stopper + kStopper_m + stroke + 0.014, kRest_m, kRod, true);
  quad(barrel, barrel_end, kBarrelRadius_m, kBarrel, false);

  // The reading beside the barrel's middle, on the side away from the view's centre, kept on the
  // display whole (the syringe may reach past its edge when the needle is shallow).
  const ImVec2 display = ImGui::GetIO().DisplaySize;
  const auto middle = at(0.5 * (barrel + barrel_end), 0.0), edge = at(0.5 * (barrel + barrel_end), kBarrelRadius_m);
  if (!middle || !edge) return;
  char lines[3][64];
  std::snprintf(lines[0], sizeof lines[0], "plunger %.0f mmHg (%.1f kPa)", y.pressure_Pa * kMmHgPerPa,
                y.pressure_Pa * 1e-3);
  std::snprintf(lines[1], sizeof lines[1], "pressed %.1f N", y.thumb_force_N);
  std::snprintf(lines[2], sizeof lines[2], "travel %.1f of %.0f mm (%s)", travel * 1e3, stroke * 1e3,
                y.fluid == 2 ? "air" : "saline");
  float width = 0.0f;
  for (const char* line : lines) width = std::max(width, ImGui::CalcTextSize(line).x);
  const float line_height = ImGui::GetTextLineHeight(),
              reach = std::hypot(edge->x - middle->x, edge->y - middle->y) + 8.0f;
  const bool left = middle->x > 0.5f * display.x;
  const float x =
      std::clamp(left ? middle->x - reach - width : middle->x + reach, 4.0f, std::max(4.0f, display.x - width - 4.0f));
  float y_px = std::clamp(middle->y - 1.5f * line_height, 4.0f, std::max(4.0f, display.y - 3.0f * line_height - 4.0f));
  for (const char* line : lines) {
    const ImVec2 p(x, y_px);
    list->AddText(ImVec2(p.x + 1.0f, p.y + 1.0f), IM_COL32(0, 0, 0, 200), line);
    list->AddText(p, kText, line);
    y_px += line_height;
  }
}

}  // namespace needle::ui
