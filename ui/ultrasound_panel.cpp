#include "ui/ultrasound_panel.hpp"

#include <imgui.h>

#include <cmath>

namespace needle::ui {

ProbeKeys probe_keys() {
  ProbeKeys keys;
  if (ImGui::GetIO().WantCaptureKeyboard) return keys;
  // ImGui 1.86's window-system backend indexes keys by the system's codes, ASCII for letters and brackets.
  keys.along = int(ImGui::IsKeyPressed('L')) - int(ImGui::IsKeyPressed('J'));
  keys.across = int(ImGui::IsKeyPressed('I')) - int(ImGui::IsKeyPressed('K'));
  keys.turn = int(ImGui::IsKeyPressed(']')) - int(ImGui::IsKeyPressed('['));
  return keys;
}

engine::ScreenRect draw_ultrasound_panel(const engine::UltrasoundProbe& shown, bool follows_needle,
                                         const std::optional<PanelPlacement>& at) {
  const ImGuiIO& io = ImGui::GetIO();
  const float height = std::round(0.45f * io.DisplaySize.y);
  const float width = std::round(height * float(shown.width_m / shown.depth_m));
  const PanelPlacement where = at.value_or(PanelPlacement{10.0f, 0.5f * io.DisplaySize.y, 0.0f, 0.5f});
  ImGui::SetNextWindowPos(ImVec2(where.x, where.y), ImGuiCond_Always, ImVec2(where.pivot_x, where.pivot_y));
  ImGui::Begin("Ultrasound", nullptr, ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoMove);
  ImGui::Text("%.1f MHz linear, %.0f mm deep, %.0f mm wide", shown.frequency_MHz, 1000.0 * shown.depth_m,
              1000.0 * shown.width_m);
  ImGui::Dummy(ImVec2(width, height));
  const ImVec2 lo = ImGui::GetItemRectMin();
  ImGui::TextUnformatted(follows_needle ? "probe follows the needle"
                                        : "move the probe: J L along, I K across, [ ] turn");
  ImGui::End();
  return engine::ScreenRect{lo.x, lo.y, width, height};
}

}  // namespace needle::ui
