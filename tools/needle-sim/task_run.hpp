// A guided task done by a scripted operator in the closed-loop simulation: simulated once, then
// played forward (all at once headless, in real time in a window), scored tick by tick as the
// haptic loop's samples would be, stored as a session, with score.json and pictures.
#pragma once

#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "arg_list.hpp"
#include "engine/needle_tracker.hpp"
#include "ui/sessions/session_store.hpp"
#include "ui/trainee_panel.hpp"

namespace needle::cli {

struct TaskRunOptions {
  std::filesystem::path task;
  std::string operator_spec = "good";  // good | sloppy | a script file
  std::string trainee;
  std::filesystem::path db;
  std::filesystem::path out_dir;
};

class ScriptedTaskRun {
 public:
  // Loads the task, simulates the operator's whole run and opens the session (incomplete until
  // finish()). Writes OUT/scenario.json, the scenario that ran.
  explicit ScriptedTaskRun(const TaskRunOptions& options);

  const ui::Task& task() const { return task_; }
  double duration_s() const { return states_.empty() ? 0.0 : states_.back().time_s; }
  // Feeds the states up to time t; on_step_end(k) runs as step k ends, with the state of that tick.
  void advance_to(double t, const std::function<void(size_t step)>& on_step_end = {});
  bool played() const { return next_ >= states_.size(); }
  // Scores, stores the session as complete and writes OUT/score.json. Once.
  const ui::SessionResult& finish();

  const engine::NeedleLoad& needle() const { return needle_; }
  // The trainee panel's view of now (with the result once finished), describing `step` when given.
  ui::TraineeView view(std::optional<size_t> step = std::nullopt) const;

 private:
  TaskRunOptions options_;
  ui::Task task_;
  std::vector<haptics::ToolSnapshot> states_;  // one per tick of the loop's period
  double period_s_ = 0.002;
  std::vector<std::string> sim_faults_;
  ui::SessionStore store_;
  int64_t session_ = 0;
  ui::SessionScorer scorer_;
  engine::NeedleTracker tracker_;
  engine::NeedleLoad needle_;
  size_t next_ = 0;
  std::optional<ui::SessionResult> result_;
};

// Headless: plays the run through, writing OUT/step_<n>_<id>.png as each step ends,
// OUT/final.png and OUT/score_panel.png. Returns 0.
int run_task_headless(const TaskRunOptions& options, Size2 size, int msaa);

}  // namespace needle::cli
