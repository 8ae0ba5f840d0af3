#include "ui/review_panels.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "training/scoring/metric_fields.hpp"
#include "ui/review_plot.hpp"
#include "ui/score_breakdown.hpp"
#include "ui/wrapped_text.hpp"

namespace needle::ui {
namespace {

const ImVec4 kGood(0.35f, 0.8f, 0.4f, 1.0f), kBad(0.9f, 0.3f, 0.25f, 1.0f), kDim(0.6f, 0.6f, 0.6f, 1.0f),
    kWarn(0.95f, 0.7f, 0.3f, 1.0f);

// A metric as the panels show it (training::MetricLabel), by its name in training::for_each_metric.
struct MetricDisplay {
  std::string name;
  training::MetricLabel shown;
};

// The metrics a session's tables show, in the list's order: the layered tissue's too on one.
std::vector<MetricDisplay> shown_metrics(bool layered) {
  std::vector<MetricDisplay> out;
  const training::Metrics none;
  training::for_each_metric(none, [&](const char* name, const auto&, const training::MetricLabel& shown) {
    if (shown.label && (layered || !shown.layered)) out.push_back({name, shown});
  });
  return out;
}

// The value of metric `d` in display units; NaN when it does not apply.
double shown_value(const training::Metrics& m, const MetricDisplay& d) {
  double out = training::kNotApplicable;
  training::for_each_metric(m, [&](const char* name, const auto& value) {
    if (d.name == name) out = d.shown.shown(double(value));
  });
  return out;
}

// A value rounded to what is worth reading (MetricLabel::decimals); "-" when it does not apply.
void value_cell(double v, int decimals = 1) {
  if (std::isnan(v)) {
    ImGui::TextColored(kDim, "-");
  } else {
    ImGui::Text("%.*f", decimals, std::abs(v) < 0.5 * std::pow(10.0, -decimals) ? 0.0 : v);  // no "-0.0"
  }
}

void header_lines(const training::SessionReview& r) {
  const training::SessionInfo& i = r.stored.info;
  ImGui::TextWrapped("Session %lld: %s, %s", static_cast<long long>(i.id), i.trainee.c_str(),
                     i.task_title.empty() ? i.task.c_str() : i.task_title.c_str());
  wrapped_text(kDim, "started %s   device %s   %.1f s", i.started_at.c_str(), i.device.empty() ? "-" : i.device.c_str(),
               i.duration_s);
  if (!i.complete) {
    wrapped_text(kWarn, "INCOMPLETE: the run ended before the task did; no score, no metrics stored");
  } else {
    ImGui::TextColored(i.passed ? kGood : kBad, "Score %.1f / 100   %s", i.score, i.passed ? "PASSED" : "NOT PASSED");
    const training::VerificationStatus v = training::verification_status(r.stored);
    ImGui::PushStyleColor(ImGuiCol_Text, v.verdict == training::Verification::kVerified   ? kGood
                                         : v.verdict == training::Verification::kMismatch ? kBad
                                                                                          : kDim);
    ImGui::TextWrapped("%s", v.line.c_str());
    ImGui::PopStyleColor();
  }
  // The device holding the force back is said, never left silent (docs/SCORING.md, "Forces").
  const double limited = r.stored.overall.force_limited_s;
  if (limited > 0.0)
    wrapped_text(kWarn, "the device held the force back at its limit for %.1f s: the hand felt less than the scene's",
                 limited);
}

void steps_table(const training::StoredSession& s, bool layered) {
  const int columns = int(s.steps.size()) + 2;
  if (s.steps.empty()) {
    ImGui::TextColored(kDim, "no step results stored");
    return;
  }
  const ImGuiTableFlags flags =
      ImGuiTableFlags_BordersInnerV | ImGuiTableFlags_RowBg | ImGuiTableFlags_SizingFixedFit | ImGuiTableFlags_ScrollX;
  const float rows = 19.5f + float(shown_metrics(layered).size() - shown_metrics(false).size());
  if (!ImGui::BeginTable("steps", columns, flags, ImVec2(0, ImGui::GetTextLineHeightWithSpacing() * rows))) return;
  ImGui::TableSetupColumn("metric");
  for (const training::StepResult& step : s.steps) ImGui::TableSetupColumn(step.id.c_str());
  ImGui::TableSetupColumn("session");
  ImGui::TableHeadersRow();
  ImGui::TableNextRow();
  ImGui::TableNextColumn();
  ImGui::TextUnformatted("outcome");
  for (const training::StepResult& step : s.steps) {
    ImGui::TableNextColumn();
    const bool ok = step.record.outcome == training::StepOutcome::kCompleted;
    ImGui::TextColored(ok ? kGood : kBad, "%s", training::step_outcome_words(step.record.outcome).c_str());
  }
  ImGui::TableNextColumn();
  ImGui::TextUnformatted(s.info.complete ? "complete" : "incomplete");
  ImGui::TableNextRow();
  ImGui::TableNextColumn();
  ImGui::TextUnformatted("start (s)");
  for (const training::StepResult& step : s.steps) {
    ImGui::TableNextColumn();
    value_cell(step.record.start_s);
  }
  ImGui::TableNextColumn();
  for (const MetricDisplay& d : shown_metrics(layered)) {
    ImGui::TableNextRow();
    ImGui::TableNextColumn();
    ImGui::Text("%s (%s)", d.shown.label, d.shown.unit);
    for (const training::StepResult& step : s.steps) {
      ImGui::TableNextColumn();
      value_cell(shown_value(step.metrics, d), d.shown.decimals);
    }
    ImGui::TableNextColumn();
    value_cell(shown_value(s.overall, d), d.shown.decimals);
  }
  ImGui::EndTable();
}

void recording_line(const training::SessionReview& r) {
  if (!r.has_recording()) {
    ImGui::TextColored(kWarn, "no plots, no replay:");
    ImGui::SameLine();
    ImGui::TextWrapped("%s", r.recording_problem.c_str());
    return;
  }
  const haptics::RecordingEnd& end = r.recording_end;
  const char* note = !end.checksummed ? " (older format, no checksums)"
                     : !end.closed    ? " (cut short: read up to its last whole block)"
                                      : "";
  wrapped_text(kDim, "recording %s: %zu samples, %.2f to %.2f s%s", r.recording_file.filename().c_str(),
               r.states.size(), r.start_s(), r.end_s(), note);
  ImGui::TextColored(r.loop.degraded() ? kWarn : kDim, "%s", training::describe(r.loop).c_str());
}

const char* step_at(const training::SessionReview& r, double t) {
  const std::vector<training::StepResult>& steps = r.stored.steps;
  for (size_t k = steps.size(); k-- > 0;) {
    if (steps[k].record.start_s <= t) return steps[k].id.c_str();
  }
  return "-";
}

// The time range typed as two numbers, and a button back to the whole session.
void span_row(const training::SessionReview& r, TimeSpan& span) {
  const TimeSpan whole{r.start_s(), r.end_s()};
  TimeSpan shown = clamped(span, whole);
  ImGui::AlignTextToFramePadding();
  ImGui::TextUnformatted("plots from");
  ImGui::SameLine();
  ImGui::SetNextItemWidth(90.0f);
  bool edited = ImGui::InputDouble("##from", &shown.lo, 0.0, 0.0, "%.2f s");
  ImGui::SameLine();
  ImGui::TextUnformatted("to");
  ImGui::SameLine();
  ImGui::SetNextItemWidth(90.0f);
  edited |= ImGui::InputDouble("##to", &shown.hi, 0.0, 0.0, "%.2f s");
  if (edited && shown.chosen()) span = clamped(shown, whole);
  ImGui::SameLine();
  if (ImGui::Button("Whole session")) span = {};
  ImGui::SameLine();
  ImGui::TextDisabled("(over a plot: wheel zooms, drag pans)");
}

}  // namespace

bool begin_panel(const char* title, const PanelRect& at, bool* open) {
  ImGui::SetNextWindowPos(at.pos, ImGuiCond_Always);
  ImGui::SetNextWindowSize(at.size, ImGuiCond_Always);
  ImGui::SetNextWindowBgAlpha(0.92f);
  return ImGui::Begin(title, open,
                      ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse |
                          ImGuiWindowFlags_NoSavedSettings);
}

void draw_session_table(const std::vector<training::SessionInfo>& sessions, SessionTableState& state,
                        const PanelRect& at) {
  if (begin_panel("Sessions", at)) {
    ImGui::SetNextItemWidth(-1.0f);
    ImGui::InputTextWithHint("##filter",
                             "filter: words in trainee, task, date, device, passed/failed/incomplete, "
                             "verified/mismatch/unverified; -word excludes",
                             state.filter, sizeof state.filter);
    const ImGuiTableFlags flags = ImGuiTableFlags_Sortable | ImGuiTableFlags_SortMulti | ImGuiTableFlags_RowBg |
                                  ImGuiTableFlags_BordersInnerV | ImGuiTableFlags_ScrollX | ImGuiTableFlags_ScrollY |
                                  ImGuiTableFlags_SizingFixedFit;
    if (ImGui::BeginTable("sessions", 9, flags)) {
      ImGui::TableSetupScrollFreeze(0, 1);
      ImGui::TableSetupColumn("ID", ImGuiTableColumnFlags_DefaultSort | ImGuiTableColumnFlags_PreferSortDescending,
                              0.0f, ImGuiID(training::SessionColumn::kId));
      ImGui::TableSetupColumn("Trainee", 0, 0.0f, ImGuiID(training::SessionColumn::kTrainee));
      ImGui::TableSetupColumn("Task", 0, 0.0f, ImGuiID(training::SessionColumn::kTask));
      ImGui::TableSetupColumn("Date (UTC)", 0, 0.0f, ImGuiID(training::SessionColumn::kDate));
      ImGui::TableSetupColumn("Score", ImGuiTableColumnFlags_PreferSortDescending, 0.0f,
                              ImGuiID(training::SessionColumn::kScore));
      ImGui::TableSetupColumn("Duration", 0, 0.0f, ImGuiID(training::SessionColumn::kDuration));
      ImGui::TableSetupColumn("Result", 0, 0.0f, ImGuiID(training::SessionColumn::kResult));
      ImGui::TableSetupColumn("Check", 0, 0.0f, ImGuiID(training::SessionColumn::kCheck));
      ImGui::TableSetupColumn("B", ImGuiTableColumnFlags_NoSort);
      ImGui::TableHeadersRow();
      if (ImGuiTableSortSpecs* specs = ImGui::TableGetSortSpecs(); specs && specs->SpecsDirty) {
        state.sort.clear();
        for (int i = 0; i < specs->SpecsCount; ++i) {
          const ImGuiTableColumnSortSpecs& s = specs->Specs[i];
          state.sort.push_back(
              {training::SessionColumn(s.ColumnUserID), s.SortDirection == ImGuiSortDirection_Descending});
        }
        specs->SpecsDirty = false;
      }
      for (size_t row : session_rows(sessions, state.filter, state.sort)) {
        const training::SessionInfo& s = sessions[row];
        ImGui::PushID(int(s.id));
        ImGui::TableNextRow();
        ImGui::TableNextColumn();
        char id[24];
        std::snprintf(id, sizeof id, "%lld", static_cast<long long>(s.id));
        if (ImGui::Selectable(id, s.id == state.selected,
                              ImGuiSelectableFlags_SpanAllColumns | ImGuiSelectableFlags_AllowItemOverlap))
          state.selected = s.id;
        ImGui::TableNextColumn();
        ImGui::TextUnformatted(s.trainee.c_str());
        ImGui::TableNextColumn();
        ImGui::TextUnformatted(s.task.c_str());
        ImGui::TableNextColumn();
        ImGui::TextUnformatted(s.started_at.c_str());
        ImGui::TableNextColumn();
        if (s.complete) {
          ImGui::Text("%5.1f", s.score);
        } else {
          ImGui::TextColored(kDim, "    -");
        }
        ImGui::TableNextColumn();
        ImGui::Text("%6.1f s", s.duration_s);
        ImGui::TableNextColumn();
        const char* word = session_result_word(s);
        ImGui::TextColored(!s.complete ? kWarn : s.passed ? kGood : kBad, "%s", word);
        ImGui::TableNextColumn();
        if (s.complete) {  // an incomplete session has no score to verify
          const training::Verification v = training::verification(s);
          ImGui::TextColored(v == training::Verification::kVerified   ? kGood
                             : v == training::Verification::kMismatch ? kBad
                                                                      : kDim,
                             "%s", training::verification_word(v));
        }
        ImGui::TableNextColumn();
        if (s.id == state.compared) {
          ImGui::TextColored(kWarn, "B");
        } else if (ImGui::SmallButton("B")) {
          state.compared = s.id;
        }
        ImGui::PopID();
      }
      ImGui::EndTable();
    }
  }
  ImGui::End();
}

bool draw_session_detail(const training::SessionReview& r, const DetailOptions& o, const PanelRect& at) {
  bool export_pressed = false;
  if (begin_panel("Session", at)) {
    header_lines(r);
    if (o.show_export) {
      export_pressed = ImGui::Button("Export CSV and JSON");
      if (!o.export_message.empty()) {
        ImGui::SameLine();
        ImGui::TextWrapped("%s", o.export_message.c_str());
      }
    }
    ImGui::Separator();
    draw_score_breakdown(r.stored.components, 2);
    ImGui::Separator();
    steps_table(r.stored, r.layered());
    ImGui::Separator();
    recording_line(r);
    PlotOptions plot;
    plot.cursor_s = r.has_recording() ? std::optional<double>(o.cursor_s) : std::nullopt;
    plot.steps = &r.stored.steps;
    plot.span = o.span;
    if (r.has_recording()) {  // else the recording line says why there are none
      if (o.span) span_row(r, *o.span);
      for (const training::Plot* p : r.plots.all()) draw_plot(*p, plot);
      if (r.layered()) draw_force_depth_plot(r.force_depth, nullptr, 140.0f);
      if (r.has_syringe()) draw_plunger_pressure_plot(r.force_depth, nullptr, 140.0f);
    }
  }
  ImGui::End();
  return export_pressed;
}

float replay_bar_height() {
  return ImGui::GetFrameHeightWithSpacing() + ImGui::GetFontSize() + 4.0f * ImGui::GetStyle().WindowPadding.y;
}

bool draw_replay_bar(const training::SessionReview& r, double& t, bool playing, const PanelRect& at) {
  if (begin_panel("Replay", at)) {
    if (!r.has_recording()) {
      wrapped_text(kWarn, "no replay: %s", r.recording_problem.c_str());
      playing = false;
    } else {
      if (ImGui::Button(playing ? "Pause" : "Play")) {
        playing = !playing;
        if (playing && t >= r.end_s()) t = r.start_s();
      }
      ImGui::SameLine();
      ImGui::SetNextItemWidth(-220.0f);
      const double lo = r.start_s(), hi = r.end_s();
      ImGui::SliderScalar("##t", ImGuiDataType_Double, &t, &lo, &hi, "%.2f s");
      ImGui::SameLine();
      ImGui::Text("step: %s", step_at(r, t));
    }
  }
  ImGui::End();
  return playing;
}

void draw_comparison(const training::SessionReview& a, const training::SessionReview& b, const PanelRect& at,
                     bool* open, TimeSpan* span) {
  if (begin_panel("Compare A and B", at, open)) {
    const training::SessionInfo &ia = a.stored.info, &ib = b.stored.info;
    ImGui::Text("A: session %lld, %s, %s", static_cast<long long>(ia.id), ia.trainee.c_str(), ia.task.c_str());
    ImGui::Text("B: session %lld, %s, %s", static_cast<long long>(ib.id), ib.trainee.c_str(), ib.task.c_str());
    if (ImGui::BeginTable("compare", 4,
                          ImGuiTableFlags_BordersInnerV | ImGuiTableFlags_RowBg | ImGuiTableFlags_SizingStretchProp)) {
      ImGui::TableSetupColumn("session");
      ImGui::TableSetupColumn("A");
      ImGui::TableSetupColumn("B");
      ImGui::TableSetupColumn("B - A");
      ImGui::TableHeadersRow();
      auto row = [](const char* label, double va, double vb, int decimals) {
        ImGui::TableNextRow();
        ImGui::TableNextColumn();
        ImGui::TextUnformatted(label);
        ImGui::TableNextColumn();
        value_cell(va, decimals);
        ImGui::TableNextColumn();
        value_cell(vb, decimals);
        ImGui::TableNextColumn();
        value_cell(vb - va, decimals);
      };
      row("score", ia.complete ? ia.score : training::kNotApplicable, ib.complete ? ib.score : training::kNotApplicable,
          1);
      for (const MetricDisplay& d : shown_metrics(a.layered())) {
        const std::string label = std::string(d.shown.label) + " (" + d.shown.unit + ")";
        row(label.c_str(), shown_value(a.stored.overall, d), shown_value(b.stored.overall, d), d.shown.decimals);
      }
      ImGui::EndTable();
    }
    ImGui::Separator();
    if (span) span_row(a, *span);
    const std::vector<const training::Plot*> pa = a.plots.all(), pb = b.plots.all();
    for (size_t k = 0; k < pa.size(); ++k) {
      PlotOptions o;
      o.height = 120.0f;
      o.span = span;
      if (pa[k]->unit == pb[k]->unit) {
        o.other = pb[k];
        draw_plot(*pa[k], o);
      } else {  // e.g. a joint-space device's tracking error against a position device's coupling force
        draw_plot(*pa[k], o);
        draw_plot(*pb[k], o);
      }
    }
    if (a.layered()) draw_force_depth_plot(a.force_depth, &b.force_depth, 120.0f);
    if (a.has_syringe()) draw_plunger_pressure_plot(a.force_depth, &b.force_depth, 120.0f);
  }
  ImGui::End();
}

void draw_force_depth_window(const training::ForceDepth& a, const training::ForceDepth* b, const PanelRect& at) {
  if (begin_panel(a.plot.title.c_str(), at))
    draw_force_depth_plot(
        a, b, std::max(80.0f, ImGui::GetContentRegionAvail().y - 2.0f * ImGui::GetTextLineHeightWithSpacing()));
  ImGui::End();
}

void draw_plunger_pressure_window(const training::ForceDepth& a, const training::ForceDepth* b, const PanelRect& at) {
  if (begin_panel(a.pressure.title.c_str(), at))
    draw_plunger_pressure_plot(
        a, b, std::max(80.0f, ImGui::GetContentRegionAvail().y - 2.0f * ImGui::GetTextLineHeightWithSpacing()));
  ImGui::End();
}

void draw_plot_window(const training::Plot& plot, const std::vector<training::StepResult>* steps, const PanelRect& at,
                      TimeSpan span) {
  if (begin_panel(plot.title.c_str(), at)) {
    PlotOptions o;
    o.span = &span;
    o.height = std::max(80.0f, ImGui::GetContentRegionAvail().y - 2.0f * ImGui::GetTextLineHeightWithSpacing());
    o.steps = steps;
    draw_plot(plot, o);
  }
  ImGui::End();
}

}  // namespace needle::ui
