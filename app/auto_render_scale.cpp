#include "app/auto_render_scale.hpp"

#include <algorithm>

namespace needle::app {

AutoRenderScale::AutoRenderScale(const AutoRenderScaleSettings& settings) : settings_(settings) {
  periods_.reserve(settings_.frames);
}

float AutoRenderScale::next(double frame_ms) {
  periods_.push_back(frame_ms);
  if (periods_.size() < settings_.frames) return scale();
  std::nth_element(periods_.begin(), periods_.begin() + periods_.size() / 2, periods_.end());
  const double median = periods_[periods_.size() / 2];
  periods_.clear();
  if (hold_ > 0) --hold_;
  if (trying_) {
    trying_ = false;
    if (median > settings_.min_gain * above_ms_) {  // no faster: back up, and wait before trying again
      --step_;
      hold_ = settings_.hold_blocks;
      return scale();
    }
  }
  if (median > settings_.budget_ms) {
    if (step_ + 1 < kSteps.size() && hold_ == 0) {
      ++step_;
      trying_ = true;
      above_ms_ = median;
    }
  } else if (step_ > 0) {
    const double grow = double(kSteps[step_ - 1]) / double(kSteps[step_]);
    if (median * grow * grow < settings_.headroom * settings_.budget_ms) --step_;
  }
  return scale();
}

}  // namespace needle::app
