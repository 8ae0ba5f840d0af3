// The view panel: how the 3D view shows the needle inside the tissue (the section view, off, cut
// or translucent) and whether the ultrasound image is shown, with their keys.
#pragma once

#include <optional>

#include "engine/scene_renderer.hpp"

namespace needle::ui {

struct ViewState {
  std::optional<engine::Section::Mode> section;  // none: the tissue whole and opaque
  bool ultrasound = false;                       // the ultrasound window shown
  bool has_ultrasound = false;                   // the view can show one (the panel offers it)
};

// Cycles off → cut → translucent → off (the X key).
void next_section_mode(ViewState& view);
// Draws the panel and applies its keys (X: section; U: ultrasound) when ImGui does not want the
// keyboard. Call inside an ImGui frame.
void draw_view_panel(ViewState& view);

}  // namespace needle::ui
