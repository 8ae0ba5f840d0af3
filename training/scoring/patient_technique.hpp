// The epidural technique on a generated patient, measured against the patient's own landmarks
// (Task::landmarks, docs/SCORING.md "Patients"): which interspace the needle entered the skin over,
// its angle to that interspace's midline approach as it entered, and how deep it was when the tip
// first reached the epidural space (the loss of resistance) against the patient's own depth there.
// The depth is measured from where the tip met the skin at rest (the skin tents a millimetre or two
// before it gives way, and the needle is "in" only from then).
// Fed one ToolSnapshot at a time on the consumer side of the sample ring; no allocation.
#pragma once

#include <optional>

#include "haptics/realtime/tool_snapshot.hpp"
#include "training/scoring/metrics.hpp"
#include "training/tasks/task.hpp"

namespace needle::training {

class PatientTechniqueTracker {
 public:
  explicit PatientTechniqueTracker(const Task& task);  // keeps a reference
  // `entry`: where the needle entered the tissue, while it is in (the session scorer's), else null.
  void feed(const haptics::ToolSnapshot& state, const Vec3* entry);
  // The four metrics into `m` (the rest untouched); not applicable where nothing happened.
  void write(Metrics& m) const;

 private:
  const Task& task_;
  int epidural_ = -1;  // the layer's index
  bool in_ = false;
  int interspace_ = -1;
  Vec3 entry_{};                  // where the needle met the skin, at rest
  std::optional<Vec3> skin_met_;  // where the tip last met the skin's surface, pressing it
  double entry_angle_deg_ = kNotApplicable, lor_depth_m_ = kNotApplicable, lor_error_m_ = kNotApplicable;
};

}  // namespace needle::training
