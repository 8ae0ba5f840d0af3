// The ultrasound probe drawn over the 3D view while its image is shown: the transducer's face on
// the skin (the array's width by a housing's thickness) and the imaged plane below it, from the
// face down to the imaging depth, so the trainee sees where the image is cut from the tissue.
// Drawn in screen space on ImGui's background draw list like the guidance (ui/guidance_overlay.hpp):
// over the scene, under the panels.
#pragma once

#include "engine/scene.hpp"
#include "engine/ultrasound.hpp"

namespace needle::ui {

// The face's thickness across the array: a design value, the footprint of a 38–50 mm linear
// probe's housing being about 10 mm across (the element's own elevation is a few mm).
inline constexpr double kProbeFaceThickness_m = 0.01;

// Call inside an ImGui frame; `camera` is the 3D view's, over the whole ImGui display.
void draw_probe(const engine::UltrasoundProbe& probe, const engine::Camera& camera);

}  // namespace needle::ui
