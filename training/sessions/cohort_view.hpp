// The instructor's class view (docs/REVIEW.md, "Cohort"): from the store's complete sessions, per
// trainee and task the score over attempts (a learning curve), first-pass success and time to
// target; across the cohort the steps most often failed and the percentiles of every metric.
// Filters by task, trainee, station and date range. No ImGui: tested against hand-counted sets.
#pragma once

#include <string>
#include <vector>

#include "training/sessions/session_store.hpp"

namespace needle::training {

struct CohortFilter {
  std::string task, trainee, station;  // "" : any
  std::string since, until;            // dates, YYYY-MM-DD, inclusive, on started_at (UTC); "": open
  bool operator==(const CohortFilter&) const = default;
};

// Throws std::invalid_argument naming the field when a date is not YYYY-MM-DD.
void check_cohort_filter(const CohortFilter& filter);

struct Attempt {
  int64_t session = 0;
  std::string started_at;
  std::string station;
  double score = 0.0;
  bool passed = false;
  double duration_s = 0.0;
  double time_to_target_s = kNotApplicable;  // end of the last completed step that has a target (tip error applies)
};

struct LearningCurve {
  std::string trainee, task;
  std::vector<Attempt> attempts;  // oldest first: attempt k is attempts[k - 1]
  bool first_pass = false;        // the first attempt passed
  int attempts_to_pass = 0;       // the first attempt that passed (1 = first), 0: none yet
};

struct StepFailures {
  std::string task, step;
  int failed = 0;    // attempts whose step ended other than completed
  int attempts = 0;  // attempts that had the step
};

struct Percentiles {
  std::string task, metric;
  size_t n = 0;  // sessions where the metric applies
  double p10 = 0, p25 = 0, p50 = 0, p75 = 0, p90 = 0;
};

struct CohortView {
  CohortFilter filter;
  std::vector<LearningCurve> curves;      // by task, then trainee
  std::vector<StepFailures> most_failed;  // most failures first (then the larger share)
  std::vector<Percentiles> percentiles;   // by task, then metric (score, duration_s, then the Metrics fields)
  size_t sessions = 0;                    // complete sessions that passed the filter
};

// What the filters can choose: the tasks, trainees and stations of the complete sessions, each
// sorted and once, empty names left out (the review window's Class tab offers them).
struct CohortChoices {
  std::vector<std::string> tasks, trainees, stations;
};
CohortChoices cohort_choices(const std::vector<SessionInfo>& sessions);

// Loads every complete session of `store` that passes `filter` and summarises them.
CohortView cohort_view(const SessionStore& store, const CohortFilter& filter);

// The p-th percentile (0-100) of `values` by linear interpolation between closest ranks (the
// "R-7" definition of numpy's default and spreadsheets' PERCENTILE); NaN for none.
double percentile(std::vector<double> values, double p);

}  // namespace needle::training
