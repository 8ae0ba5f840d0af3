#include "ui/cohort_panel.hpp"

#include <imgui.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <set>
#include <vector>

#include "training/scoring/metric_fields.hpp"
#include "training/sessions/cohort_plot.hpp"
#include "ui/review_plot.hpp"

namespace needle::ui {
namespace {

const ImVec4 kGood(0.35f, 0.8f, 0.4f, 1.0f), kBad(0.9f, 0.3f, 0.25f, 1.0f), kDim(0.6f, 0.6f, 0.6f, 1.0f),
    kWarn(0.95f, 0.7f, 0.3f, 1.0f);
const ImGuiTableFlags kTableFlags =
    ImGuiTableFlags_BordersInnerV | ImGuiTableFlags_RowBg | ImGuiTableFlags_SizingFixedFit | ImGuiTableFlags_ScrollY;

// A combo of "any" and `names` (`chosen` "" is any), the next item on its line.
void choice(const char* id, const std::vector<std::string>& names, std::string& chosen, float width) {
  ImGui::SetNextItemWidth(width);
  if (ImGui::BeginCombo(id, chosen.empty() ? "any" : chosen.c_str())) {
    if (ImGui::Selectable("any", chosen.empty())) chosen.clear();
    for (const std::string& name : names)
      if (ImGui::Selectable(name.c_str(), name == chosen)) chosen = name;
    ImGui::EndCombo();
  }
  ImGui::SameLine();
}

void number_cell(double v, const char* format = "%.4g") {
  ImGui::TableNextColumn();
  if (std::isnan(v)) {
    ImGui::TextColored(kDim, "-");
  } else {
    ImGui::Text(format, v);
  }
}

void text_cell(const std::string& s) {
  ImGui::TableNextColumn();
  ImGui::TextUnformatted(s.c_str());
}

void filter_rows(CohortPanelState& state, bool& export_pressed) {
  const float unit = ImGui::GetFontSize();
  auto label = [](const char* text) {
    ImGui::TextUnformatted(text);
    ImGui::SameLine();
  };
  auto date = [&](const char* id, char* text, size_t size) {
    ImGui::SetNextItemWidth(7.0f * unit);
    ImGui::InputTextWithHint(id, "YYYY-MM-DD", text, size);
    ImGui::SameLine();
  };
  ImGui::AlignTextToFramePadding();
  label("task");
  choice("##task", state.choices.tasks, state.task, 12.0f * unit);
  label("trainee");
  choice("##trainee", state.choices.trainees, state.trainee, 9.0f * unit);
  label("station");
  choice("##station", state.choices.stations, state.station, 9.0f * unit);
  label("from");
  date("##since", state.since, sizeof state.since);
  label("to");
  date("##until", state.until, sizeof state.until);
  ImGui::TextColored(kDim, "(UTC, inclusive)");
  if (state.show_export) {
    ImGui::SameLine();
    export_pressed = ImGui::Button("Export CSV, JSON and PNG");
    if (!state.export_message.empty()) ImGui::TextWrapped("%s", state.export_message.c_str());
  }
  if (!state.error.empty()) ImGui::TextColored(kWarn, "%s", state.error.c_str());
}

// Per trainee and task: attempts, first pass, the attempt that first passed, last and best score,
// the last attempt's time to target.
void trainees_table(const training::CohortView& view, float height) {
  if (!ImGui::BeginTable("trainees", 8, kTableFlags, ImVec2(0, height))) return;
  ImGui::TableSetupScrollFreeze(0, 1);
  for (const char* name :
       {"Trainee", "Task", "Attempts", "First pass", "Passed at", "Last score", "Best", "Time to target"})
    ImGui::TableSetupColumn(name);
  ImGui::TableHeadersRow();
  for (const training::LearningCurve& c : view.curves) {
    ImGui::TableNextRow();
    text_cell(c.trainee);
    text_cell(c.task);
    number_cell(double(c.attempts.size()), "%.0f");
    ImGui::TableNextColumn();
    ImGui::TextColored(c.first_pass ? kGood : kBad, "%s", c.first_pass ? "yes" : "no");
    ImGui::TableNextColumn();
    if (c.attempts_to_pass > 0) {
      ImGui::Text("attempt %d", c.attempts_to_pass);
    } else {
      ImGui::TextColored(kDim, "not yet");
    }
    double best = -1.0;
    for (const training::Attempt& a : c.attempts) best = std::max(best, a.score);
    number_cell(c.attempts.back().score, "%.1f");
    number_cell(best, "%.1f");
    number_cell(c.attempts.back().time_to_target_s, "%.1f s");
  }
  ImGui::EndTable();
}

void failed_steps_table(const training::CohortView& view, float height) {
  if (view.most_failed.empty()) {
    ImGui::TextColored(kDim, "no step failed");
    return;
  }
  if (!ImGui::BeginTable("failed", 4, kTableFlags, ImVec2(0, height))) return;
  ImGui::TableSetupScrollFreeze(0, 1);
  for (const char* name : {"Task", "Step", "Failed", "Share"}) ImGui::TableSetupColumn(name);
  ImGui::TableHeadersRow();
  for (const training::StepFailures& f : view.most_failed) {
    ImGui::TableNextRow();
    text_cell(f.task);
    text_cell(f.step);
    ImGui::TableNextColumn();
    ImGui::Text("%d of %d", f.failed, f.attempts);
    number_cell(100.0 * f.failed / f.attempts, "%.0f %%");
  }
  ImGui::EndTable();
}

void percentiles_table(const training::CohortView& view, float height) {
  if (!ImGui::BeginTable("percentiles", 8, kTableFlags, ImVec2(0, height))) return;
  ImGui::TableSetupScrollFreeze(0, 1);
  for (const char* name : {"Task", "Metric", "n", "p10", "p25", "p50", "p75", "p90"}) ImGui::TableSetupColumn(name);
  ImGui::TableHeadersRow();
  for (const training::Percentiles& p : view.percentiles) {
    if (p.n == 0) continue;  // a metric that applies to none of the task's sessions
    ImGui::TableNextRow();
    text_cell(p.task);
    // The metric in words with its unit and its values as the session tables show them; a metric
    // shown through a function (the jerk as smoothness) keeps its percentiles in order.
    training::MetricLabel shown = training::metric_label(p.metric);
    if (p.metric == "score") shown = {"score", "points", 1.0, false, 1};
    if (p.metric == "time_to_target_s") shown = {"time to target", "s", 1.0, false, 1};
    text_cell(shown.label ? std::string(shown.label) + " (" + shown.unit + ")" : p.metric);
    number_cell(double(p.n), "%.0f");
    std::array<double, 5> values = {p.p10, p.p25, p.p50, p.p75, p.p90};
    for (double& v : values) v = shown.shown(v);
    std::sort(values.begin(), values.end());
    char format[16];
    std::snprintf(format, sizeof format, "%%.%df", shown.decimals);
    for (double v : values) number_cell(v, format);
  }
  ImGui::EndTable();
}

}  // namespace

bool CohortPanel::update(const training::SessionStore& store, const std::vector<training::SessionInfo>& sessions) {
  std::vector<int64_t> now;
  for (const training::SessionInfo& s : sessions)
    if (s.complete) now.push_back(s.id);
  const training::CohortFilter wanted = state.filter();
  if (shown == wanted && now == complete) return false;
  state.choices = training::cohort_choices(sessions);
  shown = wanted;
  complete = std::move(now);
  try {
    view = training::cohort_view(store, wanted);
    state.error.clear();
    return true;
  } catch (const std::exception& e) {  // a date half typed, or the store failing: the last view stays
    state.error = e.what();
    return false;
  }
}

bool draw_cohort_panel(const training::CohortView& view, CohortPanelState& state, const PanelRect& at) {
  bool export_pressed = false;
  if (begin_panel("Class", at)) {
    filter_rows(state, export_pressed);
    std::set<std::string> trainees, tasks;
    for (const training::LearningCurve& c : view.curves) trainees.insert(c.trainee), tasks.insert(c.task);
    ImGui::Text("complete sessions: %zu   trainees: %zu   tasks: %zu", view.sessions, trainees.size(), tasks.size());
    ImGui::Separator();
    if (view.sessions == 0) {
      ImGui::TextColored(kDim, "No complete session passes the filters.");
    } else {
      const float line = ImGui::GetTextLineHeightWithSpacing();
      const ImVec2 room = ImGui::GetContentRegionAvail();
      ImGui::BeginChild("tables", ImVec2(0.5f * room.x, room.y));
      // Each table as tall as its rows (and a header) up to its share, the percentiles the rest.
      const float tables = ImGui::GetContentRegionAvail().y - 3.0f * line;
      auto fitted = [&](size_t rows, float share) { return std::min((float(rows) + 1.5f) * line, share * tables); };
      ImGui::TextUnformatted("Per trainee and task");
      trainees_table(view, fitted(view.curves.size(), 0.34f));
      ImGui::TextUnformatted("Steps most often failed");
      failed_steps_table(view, fitted(view.most_failed.size(), 0.22f));
      ImGui::TextUnformatted("Percentiles over the sessions");
      percentiles_table(view, ImGui::GetContentRegionAvail().y);
      ImGui::EndChild();
      ImGui::SameLine();
      ImGui::BeginChild("curves", ImVec2(0, room.y));
      PlotOptions plot;
      plot.marked_points = true;
      plot.fit_legend = true;
      // Every task's two plots in the height when they fit in it (a title and a legend line each).
      plot.height = std::max(5.0f * line, room.y / float(2 * tasks.size()) - 3.2f * line);
      for (const std::string& task : tasks)
        for (const bool time_to_target : {false, true})
          draw_plot(training::learning_curve_plot(view, task, time_to_target), plot);
      ImGui::EndChild();
    }
  }
  ImGui::End();
  return export_pressed;
}

void draw_learning_curve_window(const training::Plot& plot, const PanelRect& at) {
  if (begin_panel(plot.title.c_str(), at)) {
    PlotOptions o;
    o.marked_points = true;
    o.fit_legend = true;
    o.height = std::max(80.0f, ImGui::GetContentRegionAvail().y - 2.0f * ImGui::GetTextLineHeightWithSpacing());
    draw_plot(plot, o);
  }
  ImGui::End();
}

}  // namespace needle::ui
