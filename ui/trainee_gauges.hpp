// The trainee panel's gauges, each a bar the width of the panel with its reading in words under it
// (docs/SCORING.md, "The trainee panel"): the force at the hand against the safe limit, the sideways
// load on the needle with its warning colours, how far the step's point is, how far off the planned
// axis the needle points (with a pad showing which way to turn), and the depth along the task's axis
// with the step's band. Each kind has a colour of its own, the same as its marker over the 3D view
// where it has one (the entry's cyan, the axis's yellow, the depth band's green). Draw into the
// current ImGui window.
#pragma once

#include "training/tasks/step_cue.hpp"

namespace needle::ui {

// Where the sideways load turns orange and red: the share of the safe force at the hand (design
// values: the shipped good runs peak at 0.2 to 0.76 of it, the sloppy ones reach 3.6 times it).
inline constexpr double kSidewaysWarnShare = 0.5;
inline constexpr double kSidewaysDangerShare = 1.0;

// When the time left turns orange and red: design values, about the time a trainee in place needs to
// hold a condition (the shipped holds are 0.5 to 3 s) and a last warning.
inline constexpr double kCountdownWarn_s = 5.0;
inline constexpr double kCountdownDanger_s = 2.0;

// The time left in a step with a limit, a bar draining from full, "12 s left of 20 s".
void countdown_gauge(double left_s, double limit_s);
// The force at the hand from 0 to 1.5 times the safe limit: the safe band shaded, a force_held
// step's band outlined (band_max > band_min), the bar blue, red with its words above the limit.
void force_gauge(double force_N, double safe_N, double band_min_N, double band_max_N);
// The tissue's sideways hold on the needle at the hand (the force scale times it), on the same
// scale: blue, orange from kSidewaysWarnShare of the safe force, red from kSidewaysDangerShare.
void sideways_gauge(double sideways_at_hand_N, double safe_N);
// The distance to the step's point (cue.point), from 0 to 50 mm, the condition's tolerance ticked.
void distance_gauge(const training::Task& task, size_t step, const training::StepCue& cue);
// How far off the planned axis, from 0 to 45°, the condition's tolerance ticked.
void axis_gauge(const training::StepCue& cue);

// The turn pad's full reach: a turn of this much or more puts the dot on the pad's edge.
inline constexpr double kTurnPadFull_deg = 45.0;
// Where the turn pad's dot lies for the wrist's turn onto the axis (cue.turn_deg, cue.tilt_deg), as a
// share of the pad's half side, x to the right (clockwise as seen), y up (the hub away): the way to
// move the wrist (the mouse's drag with the right button, A/D and E/Q, the right stick), at a
// distance from the centre of √(angle / kTurnPadFull_deg), angle = √(turn² + tilt²), at most 1; the
// square root keeps the last few degrees visible (5° is a third of the way out).
struct PadPoint {
  double x = 0.0, y = 0.0;
};
PadPoint turn_pad_point(double turn_deg, double tilt_deg);
// The turn onto the planned axis at a glance: a square pad with a dot and an arrow from its centre
// the way the wrist must go (turn_pad_point), the condition's tolerance a white ring, in the axis's
// colour, its meaning in words beside it.
void turn_pad(const training::StepCue& cue);
// The depth along the gauge's marker, from 10 mm above the surface to past the deepest of the band,
// the target and 40 mm: the band green, each layer's start a pale tick, the tip a white tick.
void depth_gauge(const training::Task& task, size_t step, const training::StepCue& cue);

}  // namespace needle::ui
