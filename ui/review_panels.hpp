// The instructor's review panels (docs/REVIEW.md): the table of sessions, one session's detail
// (score breakdown, metrics per step and overall, plots over time), the replay bar and two
// sessions side by side. Each draws one ImGui window at the rectangle it is given, so the
// window and the headless report lay them out the same way.
#pragma once

#include <imgui.h>

#include <string>
#include <vector>

#include "training/sessions/session_review.hpp"
#include "training/sessions/session_table.hpp"
#include "ui/force_depth_plot.hpp"
#include "ui/time_span.hpp"

namespace needle::ui {

struct PanelRect {
  ImVec2 pos;
  ImVec2 size;
};

// Begins an ImGui window fixed at `at` (no move, resize or saved settings), as every review panel
// is; with `open`, it has a close button. End it with ImGui::End() whatever this returns.
bool begin_panel(const char* title, const PanelRect& at, bool* open = nullptr);

struct SessionTableState {
  char filter[128] = "";
  std::vector<training::SessionSort> sort{
      {training::SessionColumn::kId, true}};  // ImGui's sort specs, once it has them
  int64_t selected = 0;                       // session A, 0: none
  int64_t compared = 0;                       // session B, 0: none
};

// Click a row to review it; "B" in the last column picks the session to compare it with.
void draw_session_table(const std::vector<training::SessionInfo>& sessions, SessionTableState& state,
                        const PanelRect& at);

struct DetailOptions {
  double cursor_s = 0.0;       // the replay's time, drawn on the plots
  bool show_export = false;    // the export button (the window; the report exports by itself)
  std::string export_message;  // what the last export did
  // The plots' time range, one for all of them; with it the panel has a row to type it and a
  // button back to the whole session, and the plots zoom and pan (ui/review_plot.hpp).
  TimeSpan* span = nullptr;
};

// Returns true when the export button was pressed.
bool draw_session_detail(const training::SessionReview& review, const DetailOptions& options, const PanelRect& at);

// The replay scrubber: the time, the step running then, play and pause. Returns true while playing.
bool draw_replay_bar(const training::SessionReview& review, double& t_s, bool playing, const PanelRect& at);
// The height the replay bar needs at the frame's text size (its title and a row of buttons).
float replay_bar_height();

// Sessions A and B together: their scores and overall metrics side by side, their plots overlaid.
// With `open`, the window has a close button that clears it.
// `span`: the plots' time range, as in DetailOptions.
void draw_comparison(const training::SessionReview& a, const training::SessionReview& b, const PanelRect& at,
                     bool* open = nullptr, TimeSpan* span = nullptr);

// One plot filling a window: the report's plot pictures, of the time range `span` (unchosen: the
// whole); `steps` (may be null) their start times.
void draw_plot_window(const training::Plot& plot, const std::vector<training::StepResult>* steps, const PanelRect& at,
                      TimeSpan span = {});
inline void draw_plot_window(const training::SessionReview& review, const training::Plot& plot, const PanelRect& at,
                             TimeSpan span = {}) {
  draw_plot_window(plot, &review.stored.steps, at, span);
}

// The force–depth plot filling a window (the report's picture), B's over A's when `b` is given.
void draw_force_depth_window(const training::ForceDepth& a, const training::ForceDepth* b, const PanelRect& at);
// The plunger's pressure against depth, with a syringe (ForceDepth::pressure), as its own window.
void draw_plunger_pressure_window(const training::ForceDepth& a, const training::ForceDepth* b, const PanelRect& at);

// Whether the session's task runs on a layered tissue: its review has the force–depth plot.
inline bool layered(const training::SessionReview& r) { return r.task && r.task->layers.size() > 1; }

}  // namespace needle::ui
