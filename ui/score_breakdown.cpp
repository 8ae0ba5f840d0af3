#include "ui/score_breakdown.hpp"

#include <imgui.h>

#include <map>

namespace needle::ui {

std::string component_label(const std::string& name) {
  static const std::map<std::string, std::string> labels = {
      {"completion", "steps completed"},
      {"tip_error", "tip to target"},
      {"axis_deviation", "on the planned axis"},
      {"lateral_load", "sideways load"},
      {"peak_force", "peak force"},
      {"force_steadiness", "steady force"},
      {"path_efficiency", "direct path"},
      {"smoothness", "smoothness"},
      {"time", "time"},
      {"retries", "no re-insertions"},
      {"needle_visibility", "needle in the image"},
      {"overshoot", "overshoot"},
      {"bone_contacts", "no bone contact"},
      {"redirections", "no redirections"},
      {"loss_of_resistance", "stopped at the loss of resistance"},
  };
  const auto it = labels.find(name);
  return it != labels.end() ? it->second : name;
}

void draw_score_breakdown(const std::vector<training::ScoreComponent>& components, int columns) {
  if (components.empty()) return;
  if (!ImGui::BeginTable("breakdown", 2 * columns, ImGuiTableFlags_BordersInnerV | ImGuiTableFlags_SizingStretchProp))
    return;
  const ImVec4 dim(0.6f, 0.6f, 0.6f, 1.0f);
  for (size_t k = 0; k < components.size(); ++k) {
    const training::ScoreComponent& c = components[k];
    if (k % size_t(columns) == 0) ImGui::TableNextRow();
    ImGui::TableNextColumn();
    const bool counted = c.status == training::ComponentStatus::kApplied;
    if (counted)
      ImGui::TextUnformatted(component_label(c.name).c_str());
    else
      ImGui::TextColored(dim, "%s", component_label(c.name).c_str());
    ImGui::TableNextColumn();
    if (c.status == training::ComponentStatus::kNotApplicable)
      ImGui::TextColored(dim, "not in this task");
    else if (c.status == training::ComponentStatus::kNotReached)
      ImGui::TextColored(dim, "not reached: 0 / %.1f", c.weight);
    else
      ImGui::Text("%4.1f / %4.1f", c.points(), c.weight);
  }
  ImGui::EndTable();
}

}  // namespace needle::ui
