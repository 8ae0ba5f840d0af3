#include "training/tasks/task_progress.hpp"

#include <cmath>

#include "training/tasks/condition.hpp"

namespace needle::training {

const char* step_outcome_name(StepOutcome outcome) {
  switch (outcome) {
    case StepOutcome::kPending:
      return "pending";
    case StepOutcome::kActive:
      return "active";
    case StepOutcome::kCompleted:
      return "completed";
    case StepOutcome::kTimedOut:
      return "timed_out";
    case StepOutcome::kTipMoved:
      return "tip_moved";
    case StepOutcome::kTipLost:
      return "tip_lost";
  }
  return "unknown";
}

bool step_outcome_from_name(const std::string& name, StepOutcome& outcome) {
  for (const StepOutcome o : {StepOutcome::kPending, StepOutcome::kActive, StepOutcome::kCompleted,
                              StepOutcome::kTimedOut, StepOutcome::kTipMoved, StepOutcome::kTipLost})
    if (name == step_outcome_name(o)) {
      outcome = o;
      return true;
    }
  return false;
}

TaskProgress::TaskProgress(const Task& task) : task_(task), records_(task.steps.size()) {}

void TaskProgress::end_step(StepOutcome outcome, const haptics::ToolSnapshot& state) {
  records_[current_].outcome = outcome;
  records_[current_].end_s = state.time_s;
  held_since_s_ = std::numeric_limits<double>::quiet_NaN();
  out_of_plane_since_s_ = std::numeric_limits<double>::quiet_NaN();
  if (++current_ < records_.size()) {
    records_[current_].outcome = StepOutcome::kActive;
    records_[current_].start_s = state.time_s;
    tip_at_start_ = vec3(state.needle_tip_m);
  }
}

void TaskProgress::feed(const haptics::ToolSnapshot& state) {
  if (finished()) return;
  last_s_ = state.time_s;
  StepRecord& record = records_[current_];
  if (record.outcome == StepOutcome::kPending) {
    record.outcome = StepOutcome::kActive;
    record.start_s = state.time_s;
    tip_at_start_ = vec3(state.needle_tip_m);
  }
  const Step& step = task_.steps[current_];
  if (condition_holds(task_, step.condition, state)) {
    if (!condition_met()) held_since_s_ = state.time_s;
  } else {
    held_since_s_ = std::numeric_limits<double>::quiet_NaN();
  }
  const bool out_of_plane = step.tip_out_of_plane_max_s > 0.0 && state.contact == haptics::ContactState::kTissue &&
                            !in_image_slice(*task_.ultrasound_probe, vec3(state.needle_tip_m));
  if (!out_of_plane)
    out_of_plane_since_s_ = std::numeric_limits<double>::quiet_NaN();
  else if (std::isnan(out_of_plane_since_s_))
    out_of_plane_since_s_ = state.time_s;
  // Order of precedence on one state: success, then the tip rules, then the clock.
  if (condition_met() && state.time_s - held_since_s_ >= step.condition.hold_s)
    end_step(StepOutcome::kCompleted, state);
  else if (step.tip_fixed_within_m > 0.0 && distance(vec3(state.needle_tip_m), tip_at_start_) > step.tip_fixed_within_m)
    end_step(StepOutcome::kTipMoved, state);
  else if (out_of_plane && state.time_s - out_of_plane_since_s_ >= step.tip_out_of_plane_max_s)
    end_step(StepOutcome::kTipLost, state);
  else if (step.time_limit_s > 0.0 && state.time_s - record.start_s >= step.time_limit_s)
    end_step(StepOutcome::kTimedOut, state);
}

}  // namespace needle::training
