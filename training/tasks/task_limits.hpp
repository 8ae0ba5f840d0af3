// The range of every number a task file (assets/tasks/*.json) may hold, checked on reading
// (training/tasks/task_loader.cpp): a number outside is "FILE: /pointer: must be in RANGE, got
// VALUE". Design values, wide enough for any task the docs describe and narrow enough that a
// value past one is a typo or an attack, never a run scored on nonsense (a target "reached" within
// 1e300 m, a safe force no push exceeds). Reasons and the table: docs/TASKS.md ("Ranges").
// Positions, directions and times take the shared ranges of io/input_limits.hpp.
#pragma once

#include <cstddef>

#include "io/input_limits.hpp"

namespace needle::training::limits {

using io::Range;

// Distances a step is judged by (within_m, tip_fixed_within_m) and a sphere marker's radius: a
// needle is at most about 20 cm long and works in a body part under a metre across.
inline constexpr Range kTolerance{0.0, 1.0, true, "m"};
// A depth band along an axis: a needle reaches at most its length, 20 cm (spinal needles are
// 9 to 15 cm; biopsy needles up to 20 cm).
inline constexpr Range kDepth{0.0, 0.2, false, "m"};
// A force band and the safe force: the tissue's forces reach 10 N, a desk device renders 3 to 9 N;
// 100 N is past what a needle (or a trainee's hand on a device) exerts.
inline constexpr Range kForce{0.0, 100.0, false, "N"};
inline constexpr Range kSafeForce{0.0, 100.0, true, "N"};
// The pass mark: the score's own scale (docs/SCORING.md).
inline constexpr Range kPassScore{0.0, 100.0, false, ""};
// The normal markers' spacing [0.02 m]: they stand 1 to 3 spacings out from the surface; past
// 10 cm they leave the view.
inline constexpr Range kMarkerSpacing{0.0, 0.1, true, "m"};

// How many markers and steps a task may list: 64 each. Design value: a guided task names a few
// points and axes and takes a handful of steps (shipped: at most 4 markers, 5 steps); each marker
// is drawn every frame and each axis measured along the scenario's layers on reading, so a file
// of 100,000 (5 MB) would take minutes to read and the frames to draw.
inline constexpr size_t kMaxMarkers = 64;
inline constexpr size_t kMaxSteps = 64;

// Scoring references: the metric at which a score's term has fallen to 0 (docs/SCORING.md).
// A reference past its range scores any attempt full marks: a tip error of a metre, a deviation
// past a half turn, a lateral load of 1000 N·s (10 N for 100 s), a force wobble of 100 N, a time
// past the longest session.
inline constexpr Range kTipErrorReference{0.0, 1.0, true, "m"};
inline constexpr Range kAxisDeviationReference{0.0, 180.0, true, "deg"};
inline constexpr Range kLateralLoadReference{0.0, 1000.0, true, "N*s"};
inline constexpr Range kForceSdReference{0.0, 100.0, true, "N"};
// Normalized jerk (above sqrt(360), the minimum-jerk movement's, checked beside): up to 1e12
// (shipped: 1e6; the score's term is logarithmic in it).
inline constexpr Range kNormalizedJerkReference{0.0, 1e12, true, ""};
inline constexpr Range kOvershootReference{0.0, 1.0, true, "m"};

// The ultrasound probe: imaging depth up to 30 cm and a face up to 20 cm wide (abdominal
// curvilinear probes image to about 25-30 cm; linear arrays are 25-60 mm wide, curvilinear up to
// about 90 mm); 1 to 50 MHz (diagnostic ultrasound: 1-2 MHz for deep abdomen to 15-50 MHz for
// skin); an elevation beam up to 2 cm thick (linear probes: 1-5 mm). The shipped probe: 50 mm deep
// and wide, 7.5 MHz, 2 mm.
inline constexpr Range kProbeDepth{0.0, 0.3, true, "m"};
inline constexpr Range kProbeWidth{0.0, 0.2, true, "m"};
inline constexpr Range kProbeFrequency{1.0, 50.0, false, "MHz"};
inline constexpr Range kProbeSliceThickness{0.0, 0.02, true, "m"};

}  // namespace needle::training::limits
