// The render scale chosen from the frame's own period (TraineeFrame on a CPU device when no scale
// is fixed; docs/RENDERING.md, "Render scale"): lowered a step while the frame's tail (its 95th
// percentile, what issue 19's goal is stated on) misses its budget, back up at once when the lower
// step did not make the typical (median) frame faster (the upscale has its own cost), and raised
// a step when the tail at the larger scale would still fit with room to spare.
#pragma once

#include <array>
#include <cstddef>
#include <vector>

namespace needle::app {

struct AutoRenderScaleSettings {
  // Design value: issue 19's goal, 60 frames per second.
  double budget_ms = 1000.0 / 60.0;
  // Design value: the periods of this many frames decide (half a second at 60 fps).
  size_t frames = 30;
  // Design value: the budget is held at this percentile of a block's periods, the goal's p95; of 30
  // frames it is the second slowest, so one slow frame (a swapchain re-creation, a page of the
  // session written) moves nothing.
  double percentile = 0.95;
  // Design value: raise only when the larger scale's tail, predicted as if all of it grew with the
  // pixel count (an overestimate: the UI and presentation do not), is under this share of the
  // budget, so that the scale does not swing between two steps.
  double headroom = 0.8;
  // Design value: a step down is kept only when its first block's median is under this share of
  // the step above's (medians, as a block's tail is a frame or two, too few to compare);
  // otherwise the scale goes back up and stays for `hold_blocks` blocks (about 10 s at 60 fps)
  // before trying again, as the machine's load may have changed by then.
  double min_gain = 0.95;
  size_t hold_blocks = 20;
};

class AutoRenderScale {
 public:
  // Measured: in the trainee's window at 1280x720 on llvmpipe, with the upscale drawn on the
  // linear path (1.7 ms), 0.7 takes 0.84 of scale 1's median frame and 0.5 0.70 (docs/BENCHMARKS.md,
  // "The upscale on llvmpipe's linear path"); 0.7 is the sharper picture where it fits. Design
  // value: below half the width and height the picture gets too soft to judge a needle's tip by.
  static constexpr std::array<float, 3> kSteps{1.0f, 0.7f, 0.5f};

  explicit AutoRenderScale(const AutoRenderScaleSettings& settings = {});
  // (the last frame's period in ms) => the scale for the next frame.
  float next(double frame_ms);
  float scale() const { return kSteps[step_]; }

 private:
  AutoRenderScaleSettings settings_;
  size_t step_ = 0;
  std::vector<double> periods_;  // of the frames since the last decision
  bool trying_ = false;          // the last decision stepped down: the next block judges it
  double above_ms_ = 0.0;        // the median period of the block before that step
  size_t hold_ = 0;              // blocks left before stepping down again
};

}  // namespace needle::app
