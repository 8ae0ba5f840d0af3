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
    if (median > settings_.min_gain * above_ms_) {
      if (++looks_ < settings_.trial_blocks) return scale();  // judged again on the next block
      // No faster than the step the trials left. A lower step still may be (the level of detail
      // drops at its own thresholds: the 400x400 sphere's 0.7 draws the same mesh as 1, its 0.5 a
      // coarser one), so it is tried against the same block; past the last, back to where the
      // trials started, and wait before trying again.
      looks_ = 0;
      if (step_ + 1 < kSteps.size()) {
        ++step_;
      } else {
        trying_ = false;
        step_ = left_step_;
        hold_ = settings_.hold_blocks;
      }
      return scale();
    }
    trying_ = false;
  }
  if (tail > settings_.budget_ms) {
    if (step_ + 1 < kSteps.size() && hold_ == 0) {
      left_step_ = step_;
      ++step_;
      trying_ = true;
      looks_ = 0;
      above_ms_ = median;
    }
  } else if (step_ > 0) {
    const double grow = double(kSteps[step_ - 1]) / double(kSteps[step_]);
    if (tail * grow * grow < settings_.headroom * settings_.budget_ms) --step_;
  }
  return scale();
}

}  // namespace needle::app
