// How the trainee moved a task's ultrasound probe with the keys (app/ultrasound_window.hpp), in the
// task probe's own frame, so that it can be kept between runs (app/settings.hpp, "views") and
// applied again to the task's probe.
#pragma once

namespace needle::app {

struct ProbeOffset {
  double along_m = 0.0;   // along the task probe's array (its lateral)
  double across_m = 0.0;  // across it (its elevation)
  double turn_rad = 0.0;  // turned about its beams
  bool operator==(const ProbeOffset&) const = default;
};

}  // namespace needle::app
