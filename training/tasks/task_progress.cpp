#include "training/tasks/task_progress.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdio>

#include "haptics/syringe/loss_of_resistance.hpp"
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
    case StepOutcome::kAdvancedPastLoss:
      return "advanced_past_loss";
  }
  return "unknown";
}

bool step_outcome_from_name(const std::string& name, StepOutcome& outcome) {
  for (const StepOutcome o :
       {StepOutcome::kPending, StepOutcome::kActive, StepOutcome::kCompleted, StepOutcome::kTimedOut,
        StepOutcome::kTipMoved, StepOutcome::kTipLost, StepOutcome::kForbiddenPuncture, StepOutcome::kRigidTouched,
        StepOutcome::kAdvancedPastLoss})
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
    case StepOutcome::kAdvancedPastLoss: {
      char text[96];
      std::snprintf(text, sizeof text, "advanced %.1f mm past the loss of resistance", 1e3 * record.advanced_m);
      return text;
    }
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
  loss_found_ = false;
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
  // The loss of resistance: the syringe's flow beginning with the tip in the task's syringe space.
  const bool flowing = state.syringe.flow_m3_per_s > haptics::kLossFlow_m3_per_s && state.syringe.thumb_force_N > 0.0;
  if (step.stop_at_loss_within_m > 0.0 && !loss_found_ && flowing && !flowing_before_ && task_.syringe &&
      state.syringe.layer == task_.syringe->space) {
    loss_found_ = true;
    loss_tip_ = vec3(state.needle_tip_m);
    const auto axis = haptics::needle_axis(state);
    loss_axis_ = {axis[0], axis[1], axis[2]};
  }
  flowing_before_ = flowing;
  const double advanced = loss_found_ ? dot(vec3(state.needle_tip_m) - loss_tip_, loss_axis_) : 0.0;
  const bool seeking = step.stop_at_loss_within_m > 0.0 && !loss_found_;  // the condition counts once the loss is found
  if (!seeking && condition_holds(task_, step.condition, state)) {
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
  const bool new_touch = bone != bone_before_ &&
                         !(bone_before_ < 0 && bone_left_s_ >= 0.0 && state.time_s - bone_left_s_ < kBoneDebounce_s);
  const bool touched_now = bone >= 0 && bone < 32 && new_touch && (step.forbidden_touches >> bone & 1u);
  if (bone < 0 && bone_before_ >= 0) bone_left_s_ = state.time_s;
  punctured_before_ = state.tissue.punctured_layers;
  bone_before_ = bone;
  // Order of precedence on one state: a forbidden layer, success, then the tip rules, then the clock.
  if (passed_now != 0)
    end_step(StepOutcome::kForbiddenPuncture, state, std::countr_zero(passed_now));
  else if (touched_now)
    end_step(StepOutcome::kRigidTouched, state, bone);
  else if (loss_found_ && advanced > step.stop_at_loss_within_m) {
    records_[current_].advanced_m = advanced;
    end_step(StepOutcome::kAdvancedPastLoss, state);
  } else if (condition_met() && state.time_s - held_since_s_ >= step.condition.hold_s)
    end_step(StepOutcome::kCompleted, state);
  else if (step.tip_fixed_within_m > 0.0 && distance(vec3(state.needle_tip_m), tip_at_start_) > step.tip_fixed_within_m)
    end_step(StepOutcome::kTipMoved, state);
  else if (out_of_plane && state.time_s - out_of_plane_since_s_ >= step.tip_out_of_plane_max_s)
    end_step(StepOutcome::kTipLost, state);
  else if (step.time_limit_s > 0.0 && state.time_s - record.start_s >= step.time_limit_s)
    end_step(StepOutcome::kTimedOut, state);
}

}  // namespace needle::training
