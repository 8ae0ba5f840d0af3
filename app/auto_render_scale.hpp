// The render scale chosen from the frame's own period (TraineeFrame on a CPU device when no scale
// is fixed; docs/RENDERING.md, "Render scale"): lowered a step while the frame's tail (its 95th
// percentile, what the frame goal is stated on) misses its budget; a lower step that did not make
// the typical (median) frame faster (the upscale has its own cost) in either of its first two
// blocks is passed over for the next, and when none did, back up to where the trials started;
// raised a step when the tail at the larger scale would still fit with room to spare.
#pragma once

#include <array>
#include <cstddef>
#include <vector>

namespace needle::app {

struct AutoRenderScaleSettings {
  // Design value: the trainee's window's goal, 60 frames per second at the 95th percentile.
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
  // Design value: a step down is kept unless its first block's median is over this share of the
  // median of the step the trials left (medians, as a block's tail is a frame or two, too few to
  // compare); otherwise the next step down is tried, and when none is faster the scale goes back
  // up and stays for `hold_blocks` blocks (about 10 s at 60 fps) before trying again, as the
  // machine's load may have changed by then. Not a margin: in the window on llvmpipe two blocks'
  // medians at the same scale differ by up to a quarter (13.9 then 17.5 ms), more than the gain
  // of a step (0.84 of the frame), so a margin refused steps that pay and held a frame that
  // missed its budget for the whole hold; a step kept that is no faster costs sharpness only.
  double min_gain = 1.0;
  size_t hold_blocks = 20;
  // Design value: a step down whose first block is no faster is judged again on the next before
  // it is passed over. The same spread of block medians makes one block's judgment a toss-up
  // where the step's gain is smaller than the spread; in the trainee's window with the ultrasound
  // open a noisy block passed 0.5 over and held 0.7, whose tail missed the budget,
  // for the whole hold. A second block costs a step that truly is no faster half a second more.
  size_t trial_blocks = 2;
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
  bool trying_ = false;          // the last decision stepped down: the next blocks judge it
  size_t looks_ = 0;             // blocks of the trial judged no faster so far
  size_t left_step_ = 0;         // the step the trials left
  double above_ms_ = 0.0;        // the median period of its last block
  size_t hold_ = 0;              // blocks left before stepping down again
};

}  // namespace needle::app
