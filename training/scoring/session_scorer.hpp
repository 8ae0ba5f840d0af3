// Task progress and metrics together: the consumer side of the haptic loop's sample ring feeds
// it one TickSample at a time; it allocates nothing per sample after construction.
#pragma once

#include <optional>
#include <vector>

#include "haptics/realtime/tick_sample.hpp"
#include "training/scoring/patient_technique.hpp"
#include "training/scoring/score.hpp"
#include "training/scoring/step_metrics.hpp"
#include "training/tasks/task_progress.hpp"

namespace needle::training {

// A puncture as score.json lists it: the layer by name.
struct PunctureResult {
  std::string layer;
  double t_s = 0.0, depth_m = 0.0, peak_force_N = 0.0;
};

struct SessionResult {
  std::vector<StepResult> steps;
  Metrics overall;
  Score score;
  bool finished = false;                  // every step ended (completed or not)
  std::vector<PunctureResult> punctures;  // in order (layered tissue; at most LayerEventTracker::kMaxPunctures)
};

class SessionScorer {
 public:
  // Contact that breaks and comes back within this time is one contact: the penalty method
  // chatters at the surface on release (thesis 4.3) and that is not the trainee's doing.
  static constexpr double kContactDebounce_s = 0.25;

  explicit SessionScorer(const Task& task);  // keeps a reference: the task must outlive it

  void feed(const haptics::TickSample& sample);
  const TaskProgress& progress() const { return progress_; }
  Metrics step_metrics(size_t step) const { return steps_[step].result(); }  // live read-out
  SessionResult result() const;

 private:
  const Task& task_;
  TaskProgress progress_;
  std::vector<StepMetricsAccumulator> steps_;
  LayerEventTracker layers_;
  PatientTechniqueTracker patient_;
  SyringeEventTracker syringe_;
  ContactEvents contact_events(const haptics::ToolSnapshot& s);

  bool started_ = false;
  haptics::ContactState contact_ = haptics::ContactState::kFree;
  bool inserted_ = false;            // a tissue contact happened
  bool withdrawal_pending_ = false;  // left tissue less than the debounce time ago
  double tissue_left_s_ = 0.0;
  bool rigid_seen_ = false;
  double rigid_left_s_ = 0.0;
  uint32_t fault_ = 0;
  std::optional<Vec3> entry_;  // the tip where the needle entered the tissue, while it is in
};

}  // namespace needle::training
