// The review window's own panels around the review's (ui/review_panels.hpp, ui/cohort_panel.hpp):
// the Sessions and Class tabs across the top, and a note where a replay or a session cannot be
// shown. app/review_window.cpp lays them out and keeps their state.
#pragma once

#include <string>

#include "ui/review_panels.hpp"

namespace needle::ui {

// A panel's rectangle, in pixels from the display's top left.
PanelRect rect(float x, float y, float width, float height);

// The tabs across the top, `width` wide, and the Quit (Esc) button at their right. `select_class`
// chooses the Class tab on this frame (and is cleared). Call inside an ImGui frame.
struct ReviewTabs {
  bool class_tab = false;  // the Class tab is the one shown
  bool quit = false;       // Quit was clicked
  float height = 0.0f;     // the height the tabs take
};
ReviewTabs draw_review_tabs(float width, bool& select_class);

// `text` in a window titled `title` at `at`; a size of 0 fits the window to the text. Call inside
// an ImGui frame.
void draw_note(const char* title, const PanelRect& at, const std::string& text);

}  // namespace needle::ui
