#include "ui/input_focus.hpp"

#include <imgui.h>

namespace needle::ui {

bool pointer_on_panel() { return ImGui::GetCurrentContext() && ImGui::GetIO().WantCaptureMouse; }

bool typing() { return ImGui::GetCurrentContext() && ImGui::GetIO().WantTextInput; }

}  // namespace needle::ui
