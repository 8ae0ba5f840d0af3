// The loss-of-resistance syringe over the 3D view (docs/TASKS.md, "Syringe"): drawn on the needle's
// hub along the needle, its barrel, the fluid left in it (saline blue, air pale), the stopper and the
// plunger's rod moving in as the plunger travels, and beside it the barrel's pressure (mmHg and kPa),
// the thumb's press and the plunger's travel. It says nothing of the tissue at the tip: the plunger is
// what the trainee reads. Draw into the current ImGui frame (the background, under the panels).
#pragma once

#include "engine/scene.hpp"
#include "haptics/realtime/tool_snapshot.hpp"
#include "training/tasks/vec3.hpp"

namespace needle::ui {

// The needle's hub end, behind the tip along the needle (the needle asset's 95 mm, tools/asset-gen).
inline constexpr double kHubBehindTip_m = 0.095;

struct SyringeGaugeView {
  haptics::SyringeSnapshot syringe;    // fluid 0: nothing is drawn
  double stroke_m = 0.028;             // the plunger's travel when the syringe is empty
  training::Vec3 tip{};                // the needle, world frame
  training::Vec3 axis{1.0, 0.0, 0.0};  // unit, hub to tip
  engine::Camera camera;               // the 3D view's, over the whole ImGui display
};

void draw_syringe_gauge(const SyringeGaugeView& view);

}  // namespace needle::ui
