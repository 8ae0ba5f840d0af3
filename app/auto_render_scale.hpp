// The render scale chosen from the frame's own period (TraineeFrame on a CPU device when no scale
// is fixed; docs/RENDERING.md, "Render scale"): lowered a step while the frame misses its budget,
// back up at once when the lower step did not make the frame faster (the upscale has its own
// cost: on llvmpipe about what a 0.85 scale saves), and raised a step when the frame at the larger
// scale would still fit with room to spare.
#pragma once

#include <array>
#include <cstddef>
#include <vector>

namespace needle::app {

struct AutoRenderScaleSettings {
  // Design value: issue 19's goal, 60 frames per second.
  double budget_ms = 1000.0 / 60.0;
  // Design value: the median period of this many frames decides (half a second at 60 fps): one
  // slow frame (a swapchain re-creation, a page of the session written) moves nothing.
  size_t frames = 30;
  // Design value: raise only when the larger scale's frame, predicted as if all of it grew with the
  // pixel count (an overestimate: the UI and presentation do not), is under this share of the
  // budget, so that the scale does not swing between two steps.
  double headroom = 0.8;
  // Design value: a step down is kept only when its first block's median is under this share of
  // the step above's; otherwise the scale goes back up and stays for `hold_blocks` blocks (about
  // 10 s at 60 fps) before trying again, as the machine's load may have changed by then.
  double min_gain = 0.95;
  size_t hold_blocks = 20;
};

class AutoRenderScale {
 public:
  // Design values: 0.7 and 0.5 halve and quarter the scene's pixels; 0.85 is left out, as on
  // llvmpipe the upscale's blit (about 9 ms at 1280x720 under load, docs/BENCHMARKS.md) costs
  // what it would save; below half the width and height the picture gets too soft to judge a
  // needle's tip by.
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
  double above_ms_ = 0.0;        // the median of the block before that step
  size_t hold_ = 0;              // blocks left before stepping down again
};

}  // namespace needle::app
