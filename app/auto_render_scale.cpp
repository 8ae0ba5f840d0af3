#include "app/auto_render_scale.hpp"

#include <algorithm>
#include <cstddef>

namespace needle::app {

AutoRenderScale::AutoRenderScale(const AutoRenderScaleSettings& settings) : settings_(settings) {
  periods_.reserve(settings_.frames);
}

float AutoRenderScale::next(double frame_ms) {
  periods_.push_back(frame_ms);
  if (periods_.size() < settings_.frames) return scale();
  const auto at = [&](double share) {
    const auto nth = periods_.begin() + ptrdiff_t(share * double(periods_.size() - 1) + 0.5);
    std::nth_element(periods_.begin(), nth, periods_.end());
    return *nth;
  };
  const double median = at(0.5);
  const double tail = at(settings_.percentile);
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
  if (tail > settings_.budget_ms) {
    if (step_ + 1 < kSteps.size() && hold_ == 0) {
      ++step_;
      trying_ = true;
      above_ms_ = median;
    }
  } else if (step_ > 0) {
    const double grow = double(kSteps[step_ - 1]) / double(kSteps[step_]);
    if (tail * grow * grow < settings_.headroom * settings_.budget_ms) --step_;
  }
  return scale();
}

}  // namespace needle::app
