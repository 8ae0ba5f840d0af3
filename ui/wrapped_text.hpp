// Text that wraps at the window's edge rather than being cut there, in a colour: the panels' words
// (a gauge's reading, a warning line) stay whole at any window size.
#pragma once

#include <imgui.h>

namespace needle::ui {

// printf-style `format` in `colour`, wrapped to the window's width.
void wrapped_text(const ImVec4& colour, const char* format, ...) IM_FMTARGS(2);

}  // namespace needle::ui
