#include "ui/step_banner.hpp"

#include <imgui.h>

#include <algorithm>
#include <cstdio>

#include "training/tasks/step_cue.hpp"

namespace needle::ui {

std::optional<StepBanner> step_banner(const training::Task& task, const training::TaskProgress& progress,
                                      double now_s) {
  const std::vector<training::StepRecord>& records = progress.records();
  for (size_t k = records.size(); k-- > 0;) {
    const training::StepRecord& r = records[k];
    if (r.outcome == training::StepOutcome::kPending || r.outcome == training::StepOutcome::kActive) continue;
    if (now_s - r.end_s > kBannerSeconds || now_s < r.end_s) return std::nullopt;
    const training::Step& step = task.steps[k];
    StepBanner b;
    b.completed = r.outcome == training::StepOutcome::kCompleted;
    char head[64];
    std::snprintf(head, sizeof head, "Step %zu of %zu ", k + 1, task.steps.size());
    b.title = head + training::step_outcome_words(r.outcome) + ": " + step.id;
    if (b.completed) {
      b.detail = k + 1 < task.steps.size() ? "Next: " + task.steps[k + 1].instruction : "That was the last step.";
    } else if (r.outcome == training::StepOutcome::kTimedOut) {
      char limit[48];
      std::snprintf(limit, sizeof limit, "The %.0f s limit passed; the step needed ", step.time_limit_s);
      b.detail = limit + training::condition_words(task, step) + ".";
    } else {
      b.detail = "Why: " + training::step_failure_reason(task, r) + "; the step needed " +
                 training::condition_words(task, step) + ".";
    }
    return b;
  }
  return std::nullopt;
}

void draw_step_banner(const StepBanner& banner) {
  const ImVec2 display = ImGui::GetIO().DisplaySize;
  const float em = ImGui::GetFontSize();
  ImGui::SetNextWindowPos(ImVec2(display.x * 0.5f, 2.0f * em), ImGuiCond_Always, ImVec2(0.5f, 0.0f));
  ImGui::SetNextWindowSize(ImVec2(std::min(display.x * 0.5f, 36.0f * em), 0.0f), ImGuiCond_Always);
  ImGui::PushStyleColor(ImGuiCol_WindowBg,
                        banner.completed ? ImVec4(0.04f, 0.20f, 0.08f, 0.94f) : ImVec4(0.30f, 0.05f, 0.04f, 0.94f));
  const ImGuiWindowFlags flags = ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoSavedSettings |
                                 ImGuiWindowFlags_NoNav | ImGuiWindowFlags_NoFocusOnAppearing |
                                 ImGuiWindowFlags_NoInputs | ImGuiWindowFlags_NoMove;
  if (ImGui::Begin("step banner", nullptr, flags)) {
    ImGui::TextUnformatted(banner.title.c_str());
    ImGui::PushTextWrapPos(0.0f);
    ImGui::TextUnformatted(banner.detail.c_str());
    ImGui::PopTextWrapPos();
  }
  ImGui::End();
  ImGui::PopStyleColor();
}

}  // namespace needle::ui
