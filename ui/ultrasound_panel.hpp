// The ultrasound window's panel: an ImGui window that keeps the room for the probe's image (drawn
// into it after the panels, app/ultrasound_window.hpp), says what the probe is, and the keys that
// move a task's probe: J and L along its array, I and K across it, [ and ] about its beam.
#pragma once

#include <optional>

#include "engine/ultrasound.hpp"

namespace needle::ui {

// The presses of the probe's keys this frame, net (J: along -1, L: along +1, K: across -1,
// I: across +1, [: turn -1, ]: turn +1); none while a panel has the keyboard. Call inside an
// ImGui frame.
struct ProbeKeys {
  int along = 0, across = 0, turn = 0;
  bool any() const { return along != 0 || across != 0 || turn != 0; }
};
ProbeKeys probe_keys();

// Where the panel goes: its corner `pivot` (0 to 1 of its size) at (x, y) pixels.
struct PanelPlacement {
  float x = 0.0f, y = 0.0f, pivot_x = 0.0f, pivot_y = 0.0f;
};

// The panel for the probe `shown` (its frequency, depth and width; room for its image 0.45 of the
// display high with the image's proportions; how to move it, or that it follows the needle), at
// `at`, by default its left edge's middle at (10, half the display's height). Returns the room
// for the image. Call inside an ImGui frame.
engine::ScreenRect draw_ultrasound_panel(const engine::UltrasoundProbe& shown, bool follows_needle,
                                         const std::optional<PanelPlacement>& at);

}  // namespace needle::ui
