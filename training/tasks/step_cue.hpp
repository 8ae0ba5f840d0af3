// What is left to do in the current step, in numbers and words a novice can act on without the task
// file (docs/SCORING.md, "The trainee panel"): how far and which way the point the step is about (the entry, the
// target) lies from the tip, the turn onto the planned axis in the desk devices' own terms (turn
// clockwise as seen, tilt the hub away), the depth along the gauge's axis against the step's band,
// the force against a band to hold. The 3D view's axes come in as plain vectors: training knows no
// camera. Evaluated on the UI's side, never in the haptic tick.
#pragma once

#include <limits>
#include <string>
#include <vector>

#include "haptics/realtime/tool_snapshot.hpp"
#include "training/tasks/task.hpp"

namespace needle::training {

// The view's axes in the world frame, unit: right and up on the screen, forward into it.
struct ViewAxes {
  Vec3 right{1.0, 0.0, 0.0}, up{0.0, 0.0, 1.0}, forward{0.0, 1.0, 0.0};
};

struct StepCue {
  static constexpr double kNone = std::numeric_limits<double>::quiet_NaN();
  // The point the tip must reach (tip_near, target_reached): marker index, -1 when none.
  int point = -1;
  double distance_m = kNone;
  Vec3 to_point_view{};  // point − tip along the view's right, up and forward (into the screen), m
  // The planned axis (the condition's for axis_aligned, else the step's guidance axis), -1 when none.
  int axis = -1;
  double within_deg = kNone;    // the condition's tolerance (axis_aligned), else NaN
  double off_axis_deg = kNone;  // angle between the needle and the planned direction
  double turn_deg = 0.0;        // the swing that turns it there: about the view's direction, + clockwise as seen
  double tilt_deg = 0.0;        // and the tilt: + brings the hub away from the viewer (the tip towards them)
  // The depth gauge: the tip's depth along `gauge` (an axis: from its origin; a surface normal: under
  // the surface), -1 when the task has none; the step's band on it when the condition is one.
  int gauge = -1;
  double depth_m = kNone;
  double band_min_m = kNone, band_max_m = kNone;
};

// (task, the current step, the newest state, the view) => what is left to do.
StepCue step_cue(const Task& task, size_t step, const haptics::ToolSnapshot& state, const ViewAxes& view);

// The marker the depth gauge of `step` reads along: the condition's (depth_in_band), else the step's
// gauge, else its axis, else the nearest earlier step's, else the task's first axis or surface normal;
// -1 when the task has neither.
int gauge_marker(const Task& task, size_t step);
// The tip's depth along that marker: along an axis from its origin, under a sphere's surface (its
// radius less the tip's distance from the centre: negative above the surface).
double gauge_depth(const Marker& marker, const Vec3& tip);

// What the step's condition asks, in words: "the tip within 10 mm of the entry", "the tip 25-35 mm
// deep along the planned axis, held 0.5 s", "the needle within 5 deg of the planned axis".
std::string condition_words(const Task& task, const Step& step);

// The cue in words, one line each, most urgent first, e.g. "entry 14 mm away: 8 mm left, 11 mm down,
// 3 mm away from you", "off the axis 14°: turn clockwise 12°, tilt the hub away 8°", "depth 12 mm:
// 13 mm deeper to the band (25-35 mm)", "force 0.8 N: press harder (1.2-2.0 N)"; empty when the step
// has nothing to measure.
std::vector<std::string> cue_lines(const Task& task, size_t step, const haptics::ToolSnapshot& state,
                                   const StepCue& cue);

}  // namespace needle::training
