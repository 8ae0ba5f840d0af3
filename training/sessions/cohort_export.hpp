// The class view as files (needle-sim report --cohort; formats in docs/REVIEW.md, "Cohort"):
// cohort.json with every part, and three CSV tables (long format, one row per value).
#pragma once

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "training/sessions/cohort_view.hpp"

namespace needle::training {

// {"filter", "sessions", "curves": [{trainee, task, first_pass, attempts_to_pass, attempts: [{attempt,
// session, started_at, station, score, passed, duration_s, time_to_target_s}]}], "most_failed_steps":
// [{task, step, failed, attempts}], "percentiles": [{task, metric, n, p10, p25, p50, p75, p90}]}.
nlohmann::json cohort_json(const CohortView& view);
// trainee,task,attempt,session_id,started_at,station,score,passed,duration_s,time_to_target_s
std::string learning_curves_csv(const CohortView& view);
// task,step,failed,attempts
std::string failed_steps_csv(const CohortView& view);
// task,metric,n,p10,p25,p50,p75,p90
std::string percentiles_csv(const CohortView& view);

// Writes cohort.json, cohort_curves.csv, cohort_failed_steps.csv and cohort_percentiles.csv in
// `dir` (made when needed), each whole (io::write_file).
void export_cohort(const CohortView& view, const std::filesystem::path& dir);

}  // namespace needle::training
