// The time series the review plots, taken from a session's recording (docs/REVIEW.md,
// "Plots"): force, lateral tissue load, depth along the insertion axis and tracking error, in
// the units the plots show. No ImGui: tested against hand-computed values.
#pragma once

#include <string>
#include <vector>

#include "haptics/realtime/tick_sample.hpp"
#include "training/tasks/task.hpp"

namespace needle::training {

struct Series {
  std::string name;
  std::vector<double> t;  // s, the recording's state time (the steps' start_s and end_s clock)
  std::vector<double> v;  // in the plot's unit
};

// A horizontal line drawn across a plot: a limit or a band edge.
struct Guide {
  double value = 0.0;
  std::string label;
};

struct Plot {
  std::string title;
  std::string unit;
  std::string x_label = "t (s)";  // the x axis: a session's time, or (a learning curve) the attempt
  std::vector<Series> lines;      // empty when the plot cannot be made
  std::vector<Guide> guides;
  std::string missing;  // why there are no lines, shown instead of the plot
};

struct SessionPlots {
  Plot force;     // N: the world's force at the hand (the scored one, hand_force_N), the tissue's along the
                  // needle and the rigid contact (scene N), the hand's sensed push (operator_force_n)
  Plot lateral;   // N: |lambda| in tissue, 0 elsewhere (the integrand of lateral_load_Ns)
  Plot depth;     // mm: depth of the tip along the task's insertion axis from its origin
  Plot tracking;  // mrad: |q_m - q_v| for joint-space devices; N: coupling force for the others
  std::vector<const Plot*> all() const { return {&force, &lateral, &depth, &tracking}; }
};

// The axis marker depth is measured along: the marker of the first depth_in_band condition, or
// else of the first depth gauge; -1 when the task has neither.
int insertion_axis_marker(const Task& task);

// Every plot from the samples; `task` gives the insertion axis, the depth band and the safe
// force (nullptr: no depth plot, no guides).
SessionPlots session_plots(const std::vector<haptics::TickSample>& samples, const Task* task);

// At most 2 * bins points keeping each bin's minimum and maximum in time order, so peaks survive
// a plot narrower than the recording. Bins split the time span evenly.
Series decimate(const Series& series, size_t bins);

// Tick values for an axis from lo to hi: multiples of 1, 2 or 5 times a power of ten, at most
// `max_ticks` of them, every one inside [lo, hi].
std::vector<double> axis_ticks(double lo, double hi, int max_ticks);

}  // namespace needle::training
