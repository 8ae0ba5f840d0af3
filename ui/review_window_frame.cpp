#include "ui/review_window_frame.hpp"

#include <imgui.h>

#include <algorithm>

namespace needle::ui {

PanelRect rect(float x, float y, float width, float height) { return {ImVec2(x, y), ImVec2(width, height)}; }

ReviewTabs draw_review_tabs(float width, bool& select_class) {
  ImGui::SetNextWindowPos(ImVec2(0, 0));
  ImGui::SetNextWindowSize(ImVec2(width, 0));
  ImGui::Begin("##tabs", nullptr,
               ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoSavedSettings |
                   ImGuiWindowFlags_AlwaysAutoResize);
  ReviewTabs tabs;
  if (ImGui::BeginTabBar("view")) {
    if (ImGui::BeginTabItem("Sessions")) ImGui::EndTabItem();
    if (ImGui::BeginTabItem("Class", nullptr, select_class ? ImGuiTabItemFlags_SetSelected : 0)) {
      tabs.class_tab = true;
      ImGui::EndTabItem();
    }
    // Quit, at the bar's right end (a trailing tab button is not in Debian's ImGui).
    const char* quit = "Quit (Esc)";
    const float w = ImGui::CalcTextSize(quit).x + 2.0f * ImGui::GetStyle().FramePadding.x;
    ImGui::SameLine(std::max(ImGui::GetCursorPosX(), ImGui::GetWindowContentRegionMax().x - w));
    tabs.quit = ImGui::SmallButton(quit);
    ImGui::EndTabBar();
  }
  select_class = false;
  ImGui::End();
  tabs.height = ImGui::GetFrameHeightWithSpacing() + 2.0f * ImGui::GetStyle().WindowPadding.y;
  return tabs;
}

void draw_note(const char* title, const PanelRect& at, const std::string& text) {
  const bool fitted = at.size.x == 0.0f && at.size.y == 0.0f;
  ImGui::SetNextWindowPos(at.pos);
  if (!fitted) ImGui::SetNextWindowSize(at.size);
  ImGui::Begin(title, nullptr,
               (fitted ? ImGuiWindowFlags_AlwaysAutoResize : ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize) |
                   ImGuiWindowFlags_NoSavedSettings);
  ImGui::TextWrapped("%s", text.c_str());
  ImGui::End();
}

}  // namespace needle::ui
