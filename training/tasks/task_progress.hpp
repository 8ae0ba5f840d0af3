// Where a trainee is in a task: fed one haptic state at a time, evaluates the current step's
// condition with its hold time, applies the time limit and the fixed-tip rule, advances, and
// records each step's start, end and outcome. Allocates nothing after construction.
#pragma once

#include <limits>
#include <string>
#include <vector>

#include "haptics/realtime/tool_snapshot.hpp"
#include "training/tasks/task.hpp"

namespace needle::training {

enum class StepOutcome {
  kPending,            // not started
  kActive,             // the current step
  kCompleted,          // its condition held for its hold time
  kTimedOut,           // its time limit passed first
  kTipMoved,           // the tip drifted beyond tip_fixed_within_m first
  kTipLost,            // the tip, in tissue, stayed out of the ultrasound slice for tip_out_of_plane_max_s first
  kForbiddenPuncture,  // the track passed into one of the step's forbidden_punctures (StepRecord::layer)
  kRigidTouched,       // the tip met one of the step's forbidden_touches, a rigid layer (StepRecord::layer)
  kAdvancedPastLoss,   // the tip went on past the loss of resistance further than stop_at_loss_within_m
                       // (StepRecord::advanced_m)
};

const char* step_outcome_name(StepOutcome outcome);                          // "pending", "completed", ...
std::string step_outcome_words(StepOutcome outcome);                         // for people: "timed out", "tip moved"
bool step_outcome_from_name(const std::string& name, StepOutcome& outcome);  // false if unknown

struct StepRecord {
  StepOutcome outcome = StepOutcome::kPending;
  double start_s = std::numeric_limits<double>::quiet_NaN();
  double end_s = std::numeric_limits<double>::quiet_NaN();
  int layer = -1;  // forbidden_puncture, rigid_touched: the layer (Task::layers index)
  double advanced_m = std::numeric_limits<double>::quiet_NaN();  // advanced_past_loss: how far, along the needle
};

// Why a step ended as it did, for the trainee and the score, e.g. "dura punctured (forbidden)"; empty
// for a completed, pending or active step.
std::string step_failure_reason(const Task& task, const StepRecord& record);

class TaskProgress {
 public:
  // Bone left and met again within this time is one touch (the penalty contact chatters on release).
  static constexpr double kBoneDebounce_s = 0.25;

  explicit TaskProgress(const Task& task);  // keeps a reference: the task must outlive it

  // Takes the next state (time_s non-decreasing). The first state starts step 0; a step that
  // ends on a state starts the next one at the same time. Does nothing once finished.
  void feed(const haptics::ToolSnapshot& state);

  size_t current_step() const { return current_; }  // == steps.size() once finished
  bool finished() const { return current_ >= records_.size(); }
  const std::vector<StepRecord>& records() const { return records_; }
  bool condition_met() const { return held_since_s_ == held_since_s_; }  // on the last state
  double held_s() const { return condition_met() ? last_s_ - held_since_s_ : 0.0; }

 private:
  void end_step(StepOutcome outcome, const haptics::ToolSnapshot& state, int layer = -1);

  const Task& task_;
  std::vector<StepRecord> records_;
  size_t current_ = 0;
  double held_since_s_ = std::numeric_limits<double>::quiet_NaN();
  double last_s_ = 0.0;
  Vec3 tip_at_start_{};
  double out_of_plane_since_s_ = std::numeric_limits<double>::quiet_NaN();  // the tip in tissue, out of the slice
  uint32_t punctured_before_ = 0;                                           // the previous state's punctured layers
  int bone_before_ = -1;                                                    // and the rigid layer it touched
  double bone_left_s_ = -1.0;  // when the tip last left a rigid layer (-1: never on one)
  // The loss of resistance in a step that seeks it (Step::stop_at_loss_within_m): the syringe's flow
  // starting in the task's syringe space, where the tip was then and along which axis.
  bool flowing_before_ = false;
  bool loss_found_ = false;
  Vec3 loss_tip_{}, loss_axis_{};
};

}  // namespace needle::training
