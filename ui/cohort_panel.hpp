// The instructor's class view in the review window (docs/REVIEW.md, "Class"): what `report
// --cohort` computes (training/sessions/cohort_view.hpp), drawn: per trainee and task the attempts,
// first-pass success and time to target, the learning curves, the steps most often failed, the
// percentiles of every metric; the filters by task, trainee, station and dates; an export button.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "training/sessions/cohort_view.hpp"
#include "training/sessions/session_series.hpp"
#include "ui/review_panels.hpp"

namespace needle::ui {

struct CohortPanelState {
  training::CohortChoices choices;      // what the task, trainee and station filters offer
  std::string task, trainee, station;   // chosen, "": any
  char since[16] = "", until[16] = "";  // typed, YYYY-MM-DD, "": open
  std::string error;                    // why the view shown is not the filter's (a date half typed, a store error)
  bool show_export = false;             // the export button (the window; the report exports by itself)
  std::string export_message;           // what the last export did

  // The filter the controls say (the dates as typed: cohort_view checks them).
  training::CohortFilter filter() const { return {task, trainee, station, since, until}; }
};

// The panel's state and the view it shows of a store, computed again (cohort_view) when the filter
// or the store's complete sessions change; a filter cohort_view refuses (a date half typed) keeps
// the last view and puts the reason in state.error.
struct CohortPanel {
  CohortPanelState state;
  training::CohortView view;
  std::optional<training::CohortFilter> shown;  // the filter `view` was made with
  std::vector<int64_t> complete;                // the complete sessions it was made from

  // (store, its sessions as listed) => view, state.choices, state.error. Returns true when the view
  // was computed again.
  bool update(const training::SessionStore& store, const std::vector<training::SessionInfo>& sessions);
};

// Draws `view` with the filters above it in one window at `at`. Returns true when the export
// button was pressed.
bool draw_cohort_panel(const training::CohortView& view, CohortPanelState& state, const PanelRect& at);

// One learning curve plot (training::learning_curve_plot) filling a window: the report's PNG.
void draw_learning_curve_window(const training::Plot& plot, const PanelRect& at);

}  // namespace needle::ui
