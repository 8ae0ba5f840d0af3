// What the needle does to a layered tissue, event by event (docs/SCORING.md "Layered
// tissue"): punctures with their depth and peak force, the run of the tip after a puncture until
// it stops (the overshoot after the loss of resistance), bone contacts, redirections. Fed one
// ToolSnapshot at a time on the consumer side of the sample ring; fixed-size state, no allocation
// after construction.
#pragma once

#include <vector>

#include "haptics/realtime/tool_snapshot.hpp"
#include "training/tasks/task.hpp"

namespace needle::training {

struct PunctureRecord {
  int layer = -1;             // Task::layers index
  double t_s = 0.0;           // session time of the puncture
  double depth_m = 0.0;       // tip to the point where the needle entered the tissue
  double peak_force_N = 0.0;  // largest axial tissue force since the track's previous puncture (the pop's peak)
};

// What happened on one state.
struct LayerEvents {
  uint32_t passed = 0;               // layers the track passed into on this state (bit per layer)
  uint32_t punctured = 0;            // of those, the membranes (a puncture force): the pops
  bool bone_entry = false;           // a rigid layer met (chatter within kDebounce_s is the same contact)
  bool redirection = false;          // re-advanced deeper after a withdrawal to a shallower layer
  double run_m = kNotApplicableRun;  // the current or last run after a puncture: travel along the needle
  static constexpr double kNotApplicableRun = -1.0;
};

class LayerEventTracker {
 public:
  static constexpr double kDebounce_s = 0.25;
  static constexpr double kStopSpeed_mps = 0.002;  // design value: below 2 mm/s along the needle...
  static constexpr double kStopHold_s = 0.1;       // ...for 0.1 s, the tip has stopped (a held needle drifts < 1 mm/s)
  static constexpr size_t kMaxPunctures = 64;      // the list keeps the first ones; the count goes on

  explicit LayerEventTracker(const Task& task);  // keeps a reference
  // `entry`: where the needle entered the tissue, when in (the session scorer's), else null.
  const LayerEvents& feed(const haptics::ToolSnapshot& state, const Vec3* entry);
  const std::vector<PunctureRecord>& punctures() const { return punctures_; }

 private:
  const Task& task_;
  uint32_t membranes_ = 0;  // layers with a puncture force
  LayerEvents events_;
  bool started_ = false;
  double t_prev_ = 0.0;
  Vec3 tip_prev_{};
  uint32_t passed_prev_ = 0;
  double peak_force_ = 0.0;  // since the track's last puncture
  // Bone contact, debounced.
  bool on_bone_ = false, bone_seen_ = false;
  double bone_left_s_ = 0.0;
  // Redirection: the deepest layer of this track, whether the tip was withdrawn shallower since.
  int deepest_ = -1, shallowest_since_ = -1;
  bool withdrawn_ = false;
  // The run after a puncture.
  bool running_ = false;
  Vec3 run_start_{}, run_axis_{};
  double slow_since_s_ = -1.0;
  std::vector<PunctureRecord> punctures_;
};

}  // namespace needle::training
