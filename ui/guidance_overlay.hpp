// A step's guidance drawn over the 3D view (docs/TASKS.md, "Guidance"): the entry marker, the
// planned axis, the target, the depth gauge along its axis with the condition's band, and the
// thesis's three markers along the surface normal at the point nearest the tip (section 4.3).
// Drawn in screen space on ImGui's background draw list: over the scene (guidance shows through
// tissue, where the needle goes) and under the panels.
#pragma once

#include <imgui.h>

#include "engine/scene.hpp"
#include "training/tasks/step_cue.hpp"
#include "training/tasks/task.hpp"

namespace needle::ui {

struct GuidanceView {
  const training::Task* task = nullptr;
  size_t step = 0;
  training::Vec3 tip{};   // the needle tip, world frame (the markers' frame)
  engine::Camera camera;  // the 3D view's, over the whole ImGui display
};

void draw_guidance(const GuidanceView& view);

// The 3D view's axes in the world frame (right and up on the screen, forward into it), for the cues.
training::ViewAxes view_axes(const engine::Camera& camera);

}  // namespace needle::ui
