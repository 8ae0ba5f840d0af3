// The instructor's class view exported headless (needle-sim report --cohort): the tables of
// training/sessions/cohort_export.hpp and, per task, the learning curves as PNG.
#pragma once

#include <filesystem>
#include <string>

#include "app/messages.hpp"
#include "training/sessions/cohort_view.hpp"

namespace needle::app {

// Writes OUT/cohort.json, the CSV tables and OUT/cohort_<task>_score.png and
// OUT/cohort_<task>_time_to_target.png (a line per trainee over attempts), saying what it wrote to
// `messages`. Returns 0; throws a runtime error naming the database when it is missing or unreadable.
int write_cohort_report(const std::string& db, const training::CohortFilter& filter, const std::filesystem::path& out,
                        const Messages& messages);

}  // namespace needle::app
