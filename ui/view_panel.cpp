#include "ui/view_panel.hpp"

#include <imgui.h>

namespace needle::ui {

void next_section_mode(ViewState& view) {
  using Mode = engine::Section::Mode;
  if (!view.section)
    view.section = Mode::Cut;
  else if (*view.section == Mode::Cut)
    view.section = Mode::Translucent;
  else
    view.section.reset();
}

void draw_view_panel(ViewState& view) {
  using Mode = engine::Section::Mode;
  const ImGuiIO& io = ImGui::GetIO();
  // ImGui 1.86's window-system backend indexes keys by the system's codes, ASCII for letters.
  if (!io.WantCaptureKeyboard) {
    if (ImGui::IsKeyPressed('X', false)) next_section_mode(view);
    if (view.has_ultrasound && ImGui::IsKeyPressed('U', false)) view.ultrasound = !view.ultrasound;
  }
  ImGui::SetNextWindowPos(ImVec2(10.0f, io.DisplaySize.y - 10.0f), ImGuiCond_Always, ImVec2(0.0f, 1.0f));
  ImGui::Begin("View", nullptr, ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoMove);
  int mode = !view.section ? 0 : *view.section == Mode::Cut ? 1 : 2;
  ImGui::TextUnformatted("Section (X)");
  bool changed = ImGui::RadioButton("off", &mode, 0);
  ImGui::SameLine();
  changed |= ImGui::RadioButton("cut", &mode, 1);
  ImGui::SameLine();
  changed |= ImGui::RadioButton("translucent", &mode, 2);
  if (changed) {
    if (mode == 0)
      view.section.reset();
    else
      view.section = mode == 1 ? Mode::Cut : Mode::Translucent;
  }
  if (view.has_ultrasound) ImGui::Checkbox("Ultrasound (U)", &view.ultrasound);
  ImGui::End();
}

}  // namespace needle::ui
