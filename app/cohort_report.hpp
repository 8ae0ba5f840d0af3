// The instructor's class view exported headless (needle-sim report --cohort): the tables of
// training/sessions/cohort_export.hpp and, per task, the learning curves as PNG.
#pragma once

#include <filesystem>
#include <string>

#include "training/sessions/cohort_view.hpp"
#include "training/sessions/session_series.hpp"

namespace needle::app {

// Writes OUT/cohort.json, the CSV tables and OUT/cohort_<task>_score.png and
// OUT/cohort_<task>_time_to_target.png (a line per trainee over attempts). Returns 0; throws a
// runtime error naming the database when it is missing or unreadable.
int write_cohort_report(const std::string& db, const training::CohortFilter& filter, const std::filesystem::path& out);

// The learning curves of `task` in `view` as a plot: a line per trainee, x the attempt number,
// y the score (or, with `time_to_target`, the time to target in s; attempts without one skipped).
training::Plot learning_curve_plot(const training::CohortView& view, const std::string& task, bool time_to_target);

}  // namespace needle::app
