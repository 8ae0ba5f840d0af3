// The trainee's panel: the current step and its instruction, progress through the task, a live
// force gauge with the safe band, live metrics, the haptic loop's rate and faults; at the end,
// the score with its breakdown and what to improve. Draws into the current ImGui frame.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "training/scoring/session_scorer.hpp"
#include "training/tasks/step_cue.hpp"

namespace needle::ui {

// A button on a panel: its label (with its key, "Retry (R)") and what it does.
struct Choice {
  std::string label;
  std::function<void()> chosen;
};

struct TraineeView {
  const training::Task* task = nullptr;
  const training::TaskProgress* progress = nullptr;
  training::Metrics step_metrics;  // the current step's, live
  double now_s = 0.0;              // the newest state's time: the countdown, the banner's age
  // What is left to do in the step (training::step_cue, in the 3D view's axes) and it in words
  // (training::cue_lines): the panel's cues and its distance, axis and depth gauges.
  std::optional<training::StepCue> cue;
  std::vector<std::string> cue_lines;
  // The world's force on the needle now, by part (scene newtons), and at the hand (the task's force
  // scale times its total: what the gauge shows against the safe limit).
  training::NeedleForce needle;
  double hand_force_N = 0.0;
  bool at_device_limit = false;  // the device held the force back at its limit in the last tick
  // The layered tissue at the needle now, in a task with layers: the panel shows the
  // layer holding the tip and the punctures so far (names hidden when the task says so).
  std::optional<haptics::TissueSnapshot> tissue;
  double loop_rate_hz = 0.0;                        // measured rate of the haptic loop
  const char* fault = nullptr;                      // latched safety fault, nullptr when none
  std::function<void()> reset_fault;                // when set, a latched fault shows a button that calls it
  const training::SessionResult* result = nullptr;  // set once the task is over
  // The step to describe (a picture taken as a step ends shows that step); default: the current one.
  std::optional<size_t> step;
  const char* controls = nullptr;  // how the trainee's device moves the needle, one line
  std::vector<Choice> choices;     // buttons under the panel: Stop while running, Retry, Next task, Back at the end
};

// (view, the newest state, the task's force scale) => (view.needle, .hand_force_N, .at_device_limit):
// the gauge's numbers, as the panel shows them.
void set_forces(TraineeView& view, const haptics::ToolSnapshot& state, double force_scale);

void draw_trainee_panel(const TraineeView& view);

// The two score components that lost the most points, as advice ("Keep the needle on the
// planned axis"), most costly first; empty when nothing lost more than a point.
std::vector<std::string> what_to_improve(const training::Score& score);

}  // namespace needle::ui
