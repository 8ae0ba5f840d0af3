#include "app/replay_cursor.hpp"

namespace needle::app {

const engine::NeedleLoad& ReplayCursor::at(const std::vector<haptics::ToolSnapshot>& states, double t) {
  if (states.empty()) return load_;
  if (fed_ > 1 && states[fed_ - 1].time_s > t) reset();  // backwards: start again
  if (fed_ == 0) load_ = tracker_.update(states[fed_++]);
  for (; fed_ < states.size() && states[fed_].time_s <= t; ++fed_) load_ = tracker_.update(states[fed_]);
  return load_;
}

void ReplayCursor::reset() {
  tracker_ = NeedleTracker(kind_);
  load_ = {};
  fed_ = 0;
}

}  // namespace needle::app
