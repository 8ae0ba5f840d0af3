#include "training/tasks/task_progress.hpp"

#include <algorithm>
#include <bit>
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
    case StepOutcome::kForbiddenPuncture:
      return "forbidden_puncture";
    case StepOutcome::kRigidTouched:
      return "rigid_touched";
  }
  return "unknown";
}

bool step_outcome_from_name(const std::string& name, StepOutcome& outcome) {
  for (const StepOutcome o : {StepOutcome::kPending, StepOutcome::kActive, StepOutcome::kCompleted,
                              StepOutcome::kTimedOut, StepOutcome::kTipMoved, StepOutcome::kTipLost,
                              StepOutcome::kForbiddenPuncture, StepOutcome::kRigidTouched})
    if (name == step_outcome_name(o)) {
      outcome = o;
      return true;
    }
  return false;
}

std::string step_outcome_words(StepOutcome outcome) {
  std::string words = step_outcome_name(outcome);
  std::replace(words.begin(), words.end(), '_', ' ');
  return words;
}

std::string step_failure_reason(const Task& task, const StepRecord& record) {
  const auto layer = [&] {
    return record.layer >= 0 && size_t(record.layer) < task.layers.size() ? task.layers[size_t(record.layer)].name
                                                                           : "layer " + std::to_string(record.layer);
  };
  switch (record.outcome) {
    case StepOutcome::kPending:
    case StepOutcome::kActive:
    case StepOutcome::kCompleted:
      return "";
    case StepOutcome::kTimedOut:
      return "time limit passed";
    case StepOutcome::kTipMoved:
      return "the tip moved";
    case StepOutcome::kTipLost:
      return "the tip left the ultrasound slice";
    case StepOutcome::kForbiddenPuncture:
      return layer() + " punctured (forbidden)";
    case StepOutcome::kRigidTouched:
      return layer() + " touched (forbidden)";
  }
  return "";
}

TaskProgress::TaskProgress(const Task& task) : task_(task), records_(task.steps.size()) {}

void TaskProgress::end_step(StepOutcome outcome, const haptics::ToolSnapshot& state, int layer) {
  records_[current_].outcome = outcome;
  records_[current_].end_s = state.time_s;
  records_[current_].layer = layer;
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
  // A forbidden layer passed into or a forbidden rigid layer met on this state (not one the track
  // or the tip was already in: the fault is the event).
  const uint32_t passed_now = state.tissue.punctured_layers & ~punctured_before_ & step.forbidden_punctures;
  // A touch is the tip meeting bone it was not on; leaving and meeting it again within the
  // contact debounce is the penalty's chatter (docs/SCORING.md), the same touch.
  const int bone = state.tissue.bone_layer;
  const bool new_touch = bone != bone_before_ && !(bone_before_ < 0 && bone_left_s_ >= 0.0 &&
                                                   state.time_s - bone_left_s_ < kBoneDebounce_s);
  const bool touched_now = bone >= 0 && bone < 32 && new_touch && (step.forbidden_touches >> bone & 1u);
  if (bone < 0 && bone_before_ >= 0) bone_left_s_ = state.time_s;
  punctured_before_ = state.tissue.punctured_layers;
  bone_before_ = bone;
  // Order of precedence on one state: a forbidden layer, success, then the tip rules, then the clock.
  if (passed_now != 0)
    end_step(StepOutcome::kForbiddenPuncture, state, std::countr_zero(passed_now));
  else if (touched_now)
    end_step(StepOutcome::kRigidTouched, state, bone);
  else if (condition_met() && state.time_s - held_since_s_ >= step.condition.hold_s)
    end_step(StepOutcome::kCompleted, state);
  else if (step.tip_fixed_within_m > 0.0 && distance(vec3(state.needle_tip_m), tip_at_start_) > step.tip_fixed_within_m)
    end_step(StepOutcome::kTipMoved, state);
  else if (out_of_plane && state.time_s - out_of_plane_since_s_ >= step.tip_out_of_plane_max_s)
    end_step(StepOutcome::kTipLost, state);
  else if (step.time_limit_s > 0.0 && state.time_s - record.start_s >= step.time_limit_s)
    end_step(StepOutcome::kTimedOut, state);
}

}  // namespace needle::training
