// The force–depth plot of a layered session (docs/REVIEW.md, "Force against depth"): the axial
// force against the depth along the track, one line per track, the depths where the tip first
// entered each layer as dashed lines named by layer, the punctures as rings at their peak; a
// second session's lines and punctures over the first for comparison. Beside it, with a syringe,
// the plunger's pressure against the same depth with the losses of resistance as rings.
#pragma once

#include "training/sessions/force_depth.hpp"

namespace needle::ui {

// Draws at the cursor, the width available, `height` pixels and the legend below. `b` may be null.
void draw_force_depth_plot(const training::ForceDepth& a, const training::ForceDepth* b, float height);
// The plunger's pressure against depth (ForceDepth::pressure, ::losses), drawn the same way.
void draw_plunger_pressure_plot(const training::ForceDepth& a, const training::ForceDepth* b, float height);

}  // namespace needle::ui
