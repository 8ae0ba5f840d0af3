// The force–depth picture of a session on a layered tissue (docs/REVIEW.md "Force
// against depth"): the tissue's axial force on the needle against the tip's depth along the track,
// where the tip first entered each layer, and the punctures, each with its peak. No ImGui: tested
// against the recording's own states.
#pragma once

#include <string>
#include <vector>

#include "haptics/realtime/tick_sample.hpp"
#include "training/scoring/session_scorer.hpp"
#include "training/sessions/session_series.hpp"
#include "training/tasks/task.hpp"

namespace needle::training {

// A point marked on the plot: x the depth (mm), y the force (N).
struct PlotMark {
  double x = 0.0, y = 0.0;
  std::string label;
};

struct ForceDepth {
  // x (Series::t): depth in mm along the track; v: the axial force in N (ToolSnapshot::tissue).
  // One line per track (a full withdrawal ends one), in the recording's order: the x values are
  // not sorted (the needle is pulled back along the same depths).
  Plot plot;
  std::vector<PlotMark> boundaries;  // y unused: the depth where the tip first entered each layer, labelled by name
  std::vector<PlotMark> punctures;   // at the puncture's depth and peak force, labelled by layer
  std::vector<PunctureResult> puncture_list;  // as score.json lists them (the session scorer's, replayed)
  // With a syringe (ToolSnapshot::syringe): the barrel's pressure against the same depth, in kPa, one
  // line per track as `plot`, and each loss of resistance at its depth and the pressure before it,
  // labelled by the layer the fluid went into ("false" when it is not the task's syringe space).
  Plot pressure;
  std::vector<PlotMark> losses;
};

// Points closer than this in depth to the last one kept are left out of a track's line when the
// force moved less than kForceStep_N (a recording holds thousands of ticks per millimetre held):
// design values, a hundredth of a millimetre and of a newton, below what a plot shows.
inline constexpr double kDepthStep_mm = 0.01;
inline constexpr double kForceStep_N = 0.01;
inline constexpr double kPressureStep_kPa = 0.1;  // and of the plunger's pressure: a tenth of a kPa (0.75 mmHg)

// The depth along a track: from the tip where the needle first met the tissue (a surface pressed
// or a layer holding the tip), along the needle's axis then; the track ends when the needle is
// out with no layer passed. The punctures are the session scorer's, fed the samples as the run
// fed it, each placed at the depth of its own state. `task` null, or a tissue of one layer: no
// plot (`missing` says why).
ForceDepth force_depth(const std::vector<haptics::TickSample>& samples, const Task* task);

}  // namespace needle::training
