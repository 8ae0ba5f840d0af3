// The review's replay: the recorded states played back into the 3D view. The needle tracker is
// stateful (it remembers where the needle entered the tissue), so the cursor feeds it forward
// from where it was and starts again from the first state when scrubbed backwards.
#pragma once

#include <vector>

#include "app/needle_tracker.hpp"

namespace needle::app {

class ReplayCursor {
 public:
  explicit ReplayCursor(TissueKind kind = TissueKind::SingleSurface) : tracker_(kind), kind_(kind) {}

  // The needle at the last state with time_s <= t (the first state when t is before it).
  // `states` must stay the same between calls (a new recording: a new cursor).
  const engine::NeedleLoad& at(const std::vector<haptics::ToolSnapshot>& states, double t);

 private:
  void reset();

  NeedleTracker tracker_;
  TissueKind kind_;
  engine::NeedleLoad load_;
  size_t fed_ = 0;  // states fed to the tracker
};

}  // namespace needle::app
