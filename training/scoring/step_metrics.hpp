// Accumulates the metrics of one step from the haptic states that fall in it. Fixed-size state.
#pragma once

#include "haptics/realtime/tool_snapshot.hpp"
#include "training/scoring/layer_events.hpp"
#include "training/scoring/metrics.hpp"
#include "training/scoring/needle_force.hpp"
#include "training/scoring/syringe_events.hpp"
#include "training/scoring/trajectory_metrics.hpp"
#include "training/tasks/task.hpp"

namespace needle::training {

// Contact events the session tracks across steps and attributes to the step they happen in.
struct ContactEvents {
  bool withdrawal = false;                 // tissue -> free
  bool reinsertion = false;                // free -> tissue after an earlier insertion
  bool rigid_entry = false;                // -> rigid surface
  bool fault = false;                      // a fault latched on this state
  const Vec3* entry = nullptr;             // while in tissue: where the needle entered it
  const LayerEvents* layers = nullptr;     // the layered tissue's events on this state, when tracked
  const SyringeEvents* syringe = nullptr;  // the syringe's, in a task with one
};

class StepMetricsAccumulator {
 public:
  StepMetricsAccumulator(const Task& task, const Step& step);
  void add(const haptics::ToolSnapshot& state, const ContactEvents& events);
  Metrics result() const;

 private:
  const Task& task_;
  const Step& step_;
  int target_ = -1;                // point marker the tip error is measured to
  int axis_ = -1;                  // axis marker the deviation is measured from
  bool deviation_at_end_ = false;  // alignment steps: how well aligned at the end, not on the way
  bool planned_rigid_ = false;
  long samples_ = 0;
  double t_prev_ = 0.0;
  Vec3 tip_{};
  double last_deviation_rad_ = 0.0, deviation_sq_sum_ = 0.0;
  double lateral_prev_ = 0.0;
  // Force while holding: Welford running mean and variance from the first time it entered the band.
  bool in_band_seen_ = false;
  long force_n_ = 0;
  double force_mean_ = 0.0, force_m2_ = 0.0;
  // The needle's share in the ultrasound slice, integrated over the time in tissue.
  double visible_integral_s_ = 0.0, tissue_time_s_ = 0.0, visible_prev_ = 0.0;
  bool in_tissue_prev_ = false;
  double run_m_ = LayerEvents::kNotApplicableRun;  // the last run after a puncture seen in this step
  Metrics m_;
  PathAccumulator path_;
};

}  // namespace needle::training
