#include "ui/trainee_panel.hpp"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <map>

#include "ui/score_breakdown.hpp"
#include "ui/step_banner.hpp"
#include "ui/trainee_gauges.hpp"
#include "ui/wrapped_text.hpp"

namespace needle::ui {
namespace {

const ImVec4 kGood(0.35f, 0.8f, 0.4f, 1.0f), kBad(0.9f, 0.3f, 0.25f, 1.0f), kDim(0.6f, 0.6f, 0.6f, 1.0f);

// The world's force on the needle by what makes it, as the tissue and bone push it (scene newtons).
void needle_force_line(const training::NeedleForce& f) {
  ImGui::TextWrapped("on the needle: along %.2f N, sideways %.2f N, bone %.2f N", f.along_N, f.sideways_N, f.rigid_N);
}

void metric_line(const char* name, double value, const char* unit, double scale = 1.0) {
  if (std::isnan(value)) {
    ImGui::TextColored(kDim, "%-16s -", name);
  } else {
    ImGui::Text("%-16s %.2f %s", name, value * scale, unit);
  }
}

// A layer as the trainee may see it: its name, or its number when the task hides the names.
std::string layer_label(const training::Task& task, int layer) {
  if (task.hide_layer_names || layer < 0 || size_t(layer) >= task.layers.size())
    return "layer " + std::to_string(layer + 1);
  return task.layers[size_t(layer)].name;
}

// The layer holding the tip and the membranes punctured on the track so far.
void tissue_lines(const training::Task& task, const haptics::TissueSnapshot& t) {
  if (t.tip_layer >= 0)
    ImGui::Text("tip in: %s", layer_label(task, t.tip_layer).c_str());
  else
    ImGui::TextColored(kDim, "tip in: -");
  std::string punctured;
  int count = 0;
  for (size_t i = 0; i < task.layers.size() && i < 32; ++i)
    if (task.layers[i].puncture_force_N > 0.0 && haptics::punctured(t, int(i))) {
      ++count;
      if (!task.hide_layer_names) punctured += (punctured.empty() ? "" : ", ") + task.layers[i].name;
    }
  ImGui::TextWrapped("punctures: %d%s%s%s", count, punctured.empty() ? "" : " (", punctured.c_str(),
                     punctured.empty() ? "" : ")");
  if (t.bone_layer >= 0) ImGui::TextColored(kBad, "on bone: %s", layer_label(task, t.bone_layer).c_str());
}

// The step's clock: the time left of its limit, or that it has none.
void step_clock(const TraineeView& v, const training::Step& step, const training::StepRecord& record) {
  if (step.time_limit_s > 0.0)
    countdown_gauge(step.time_limit_s - (v.now_s - record.start_s), step.time_limit_s);
  else
    ImGui::TextColored(kDim, v.task->practice ? "practice: no time limit" : "no time limit");
}

// What to do now, in words, the most urgent first.
void cue_list(const std::vector<std::string>& lines) {
  for (const std::string& line : lines) {
    ImGui::Bullet();
    ImGui::TextWrapped("%s", line.c_str());
  }
}

void draw_running(const TraineeView& v) {
  const training::Task& task = *v.task;
  const size_t shown = std::min(v.step.value_or(v.progress->current_step()), task.steps.size() - 1);
  const training::Step& step = task.steps[shown];
  const training::StepRecord& record = v.progress->records()[shown];
  ImGui::Text("Step %zu of %zu: %s", shown + 1, task.steps.size(), step.id.c_str());
  ImGui::ProgressBar(float(v.progress->current_step()) / float(task.steps.size()), ImVec2(-1, 0));
  ImGui::Separator();
  ImGui::TextWrapped("%s", step.instruction.c_str());
  if (record.outcome == training::StepOutcome::kActive) {
    step_clock(v, step, record);
    if (v.progress->condition_met()) ImGui::TextColored(kGood, "holding... %.1f s", v.progress->held_s());
    cue_list(v.cue_lines);
  } else {
    const std::string why = training::step_failure_reason(task, record);
    wrapped_text(record.outcome == training::StepOutcome::kCompleted ? kGood : kBad, "%s%s%s",
                 training::step_outcome_words(record.outcome).c_str(), why.empty() ? "" : ": ", why.c_str());
  }
  if (v.cue) {
    distance_gauge(task, shown, *v.cue);
    axis_gauge(*v.cue);
    turn_pad(*v.cue);
    depth_gauge(task, shown, *v.cue);
  }
  ImGui::Separator();
  const bool force_band = step.condition.type == training::ConditionType::kForceHeld;
  const double safe = task.scoring.safe_force_N;
  force_gauge(v.hand_force_N, safe, force_band ? step.condition.min : 0.0, force_band ? step.condition.max : 0.0);
  sideways_gauge(task.force_scale * v.needle.sideways_N, safe);
  needle_force_line(v.needle);
  if (v.at_device_limit) wrapped_text(kBad, "the device is at its force limit: you feel less than this");
  if (v.tissue) tissue_lines(task, *v.tissue);
  ImGui::Separator();
  const training::Metrics& m = v.step_metrics;
  metric_line("sideways load", m.lateral_load_Ns, "N s");
  metric_line("peak at the hand", m.peak_hand_force_N, "N");
}

void draw_result(const training::SessionResult& r) {
  ImGui::TextColored(r.score.passed ? kGood : kBad, "Score %.0f / 100  %s", r.score.total,
                     r.score.passed ? "PASSED" : "NOT PASSED");
  ImGui::Separator();
  draw_score_breakdown(r.score.components, 1);
  // A layered task's faults by name (the sloppy epidural's bone contact or
  // dural puncture is named in the panel, not only as a component's lost points).
  const training::Metrics& m = r.overall;
  if (m.bone_contacts > 0 || m.forbidden_punctures > 0 || m.redirections > 0) ImGui::Separator();
  if (m.bone_contacts > 0)
    wrapped_text(kBad, "bone contacts: %u (peak %.1f N on the bone)", m.bone_contacts, m.bone_peak_force_N);
  if (m.forbidden_punctures > 0) ImGui::TextColored(kBad, "forbidden punctures: %u", m.forbidden_punctures);
  if (m.redirections > 0) ImGui::TextColored(kBad, "redirections: %u", m.redirections);
  std::vector<std::string> advice = what_to_improve(r.score);
  for (const std::string& why : r.score.reasons_failed) advice.push_back(why);
  if (!advice.empty()) {
    ImGui::Separator();
    ImGui::TextUnformatted("What to improve:");
    for (const std::string& a : advice) {
      ImGui::Bullet();
      ImGui::TextWrapped("%s", a.c_str());
    }
  }
}

}  // namespace

void set_forces(TraineeView& view, const haptics::ToolSnapshot& state, double force_scale) {
  view.needle = training::needle_force(state);
  view.hand_force_N = force_scale * view.needle.total_N;
  view.at_device_limit = (state.limits & haptics::kLimitForce) != 0;
}

std::vector<std::string> what_to_improve(const training::Score& score) {
  static const std::map<std::string, std::string> advice = {
      {"completion", "Finish every step before its time runs out"},
      {"tip_error", "Bring the tip closer to the target"},
      {"axis_deviation", "Keep the needle on the planned axis"},
      {"lateral_load", "Do not push the needle sideways in the tissue"},
      {"peak_force", "Press more gently: stay inside the safe force band"},
      {"force_steadiness", "Hold the force steadier"},
      {"path_efficiency", "Move more directly to the target"},
      {"smoothness", "Move more smoothly"},
      {"time", "Work a little faster"},
      {"retries", "Avoid withdrawing and re-inserting"},
      {"overshoot", "Stop as soon as the resistance gives way"},
      {"bone_contacts", "Keep to the planned axis: do not meet the bone"},
      {"redirections", "Aim before you go in: avoid pulling back and redirecting"},
      {"loss_of_resistance", "Stop as soon as the plunger gives way, and do not mistake a give"},
  };
  std::vector<const training::ScoreComponent*> lost;
  // What the trainee did, not what the run never reached (the steps not completed say that).
  for (const training::ScoreComponent& c : score.components) {
    if (c.status == training::ComponentStatus::kApplied && c.weight - c.points() > 1.0) lost.push_back(&c);
  }
  std::sort(lost.begin(), lost.end(), [](const training::ScoreComponent* a, const training::ScoreComponent* b) {
    return a->weight - a->points() > b->weight - b->points();
  });
  std::vector<std::string> out;
  for (size_t i = 0; i < lost.size() && i < 2; ++i) {
    auto it = advice.find(lost[i]->name);
    out.push_back(it != advice.end() ? it->second : "Improve " + lost[i]->name);
  }
  return out;
}

void draw_trainee_panel(const TraineeView& v) {
  const ImVec2 display = ImGui::GetIO().DisplaySize;
  ImGui::SetNextWindowPos(ImVec2(display.x - 10.0f, 10.0f), ImGuiCond_Always, ImVec2(1.0f, 0.0f));
  ImGui::SetNextWindowSize(ImVec2(340.0f * ImGui::GetFontSize() / 13.0f, 0.0f),
                           ImGuiCond_Always);  // 340 px at 13 px text
  ImGui::SetNextWindowBgAlpha(0.85f);
  const ImGuiWindowFlags flags = ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoCollapse |
                                 ImGuiWindowFlags_NoSavedSettings;
  if (ImGui::Begin("Task", nullptr, flags)) {
    ImGui::TextWrapped("%s", v.task->title.c_str());
    ImGui::Separator();
    if (v.result) {
      draw_result(*v.result);
    } else {
      draw_running(v);
    }
    ImGui::Separator();
    if (v.fault) {
      ImGui::TextColored(kBad, "haptic loop %.0f Hz   FAULT: %s", v.loop_rate_hz, v.fault);
      if (v.reset_fault) {
        ImGui::SameLine();
        if (ImGui::SmallButton("Reset fault")) v.reset_fault();  // the only way a fault clears
      }
    } else {
      ImGui::TextColored(kDim, "haptic loop %.0f Hz   no fault", v.loop_rate_hz);
    }
    if (v.controls && !v.result) {
      ImGui::Separator();
      ImGui::TextWrapped("%s", v.controls);
    }
    if (!v.choices.empty()) {
      ImGui::Separator();
      for (size_t i = 0; i < v.choices.size(); ++i) {
        if (i > 0) ImGui::SameLine();
        if (ImGui::Button(v.choices[i].label.c_str())) v.choices[i].chosen();
      }
    }
  }
  ImGui::End();
  if (!v.result)
    if (const std::optional<StepBanner> banner = step_banner(*v.task, *v.progress, v.now_s)) draw_step_banner(*banner);
}

}  // namespace needle::ui
