// The class view's learning curves as plots (training/sessions/session_series.hpp's Plot), drawn
// by the review window's Class tab and written as PNG by `report --cohort`.
#pragma once

#include <string>

#include "training/sessions/cohort_view.hpp"
#include "training/sessions/session_series.hpp"

namespace needle::training {

// The learning curves of `task` in `view` as a plot: a line per trainee, x the attempt number,
// y the score (or, with `time_to_target`, the time to target in s; attempts without one skipped).
Plot learning_curve_plot(const CohortView& view, const std::string& task, bool time_to_target);

}  // namespace needle::training
