#include "training/sessions/cohort_view.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <stdexcept>

#include "training/scoring/metric_fields.hpp"

namespace needle::training {

namespace {

// YYYY-MM-DD, a day of the Gregorian calendar: 2026-02-30 and 2026-13-45 are none.
bool is_date(const std::string& d) {
  if (d.size() != 10 || d[4] != '-' || d[7] != '-') return false;
  for (size_t i : {0, 1, 2, 3, 5, 6, 8, 9})
    if (!std::isdigit(static_cast<unsigned char>(d[i]))) return false;
  const int year = std::stoi(d.substr(0, 4)), month = std::stoi(d.substr(5, 2)), day = std::stoi(d.substr(8, 2));
  const bool leap = (year % 4 == 0 && year % 100 != 0) || year % 400 == 0;
  const int days[12] = {31, leap ? 29 : 28, 31, 30, 31, 30, 31, 31, 30, 31, 30, 31};
  return month >= 1 && month <= 12 && day >= 1 && day <= days[month - 1];
}

bool passes(const SessionInfo& s, const CohortFilter& f) {
  const std::string day = s.started_at.substr(0, 10);
  return s.complete && (f.task.empty() || s.task == f.task) && (f.trainee.empty() || s.trainee == f.trainee) &&
         (f.station.empty() || s.station == f.station) && (f.since.empty() || day >= f.since) &&
         (f.until.empty() || day <= f.until);
}

double time_to_target(const StoredSession& s) {
  double t = kNotApplicable;
  for (const StepResult& step : s.steps)
    if (step.record.outcome == StepOutcome::kCompleted && !std::isnan(step.metrics.tip_error_m)) t = step.record.end_s;
  return t;
}

}  // namespace

void check_cohort_filter(const CohortFilter& filter) {
  if (!filter.since.empty() && !is_date(filter.since))
    throw std::invalid_argument("--since: expected a date YYYY-MM-DD, got '" + filter.since + "'");
  if (!filter.until.empty() && !is_date(filter.until))
    throw std::invalid_argument("--until: expected a date YYYY-MM-DD, got '" + filter.until + "'");
}

double percentile(std::vector<double> values, double p) {
  if (values.empty()) return kNotApplicable;
  std::sort(values.begin(), values.end());
  const double rank = p / 100.0 * double(values.size() - 1);
  const size_t lo = size_t(std::floor(rank));
  const size_t hi = std::min(lo + 1, values.size() - 1);
  return values[lo] + (rank - double(lo)) * (values[hi] - values[lo]);
}

CohortChoices cohort_choices(const std::vector<SessionInfo>& sessions) {
  std::set<std::string> tasks, trainees, stations;
  for (const SessionInfo& s : sessions) {
    if (!s.complete) continue;
    for (auto [set, value] : {std::pair{&tasks, &s.task}, {&trainees, &s.trainee}, {&stations, &s.station}})
      if (!value->empty()) set->insert(*value);  // "" (a station before schema 3) cannot be filtered on
  }
  return {{tasks.begin(), tasks.end()}, {trainees.begin(), trainees.end()}, {stations.begin(), stations.end()}};
}

CohortView cohort_view(const SessionStore& store, const CohortFilter& filter) {
  check_cohort_filter(filter);
  CohortView view;
  view.filter = filter;
  std::map<std::pair<std::string, std::string>, LearningCurve> curves;        // (task, trainee)
  std::map<std::pair<std::string, std::string>, StepFailures> failures;       // (task, step)
  std::map<std::pair<std::string, std::string>, std::vector<double>> values;  // (task, metric)
  std::vector<std::string> metric_order = {"score", "duration_s", "time_to_target_s"};
  const Metrics names_of;
  for_each_metric(names_of, [&](const char* name, const auto&) {
    if (std::string(name) != "duration_s") metric_order.push_back(name);
  });
  std::vector<SessionInfo> list = store.sessions();
  std::sort(list.begin(), list.end(), [](const SessionInfo& a, const SessionInfo& b) {
    return a.started_at != b.started_at ? a.started_at < b.started_at : a.id < b.id;
  });
  for (const SessionInfo& info : list) {
    if (!passes(info, filter)) continue;
    ++view.sessions;
    const StoredSession s = store.load(info.id);
    LearningCurve& curve = curves[{info.task, info.trainee}];
    curve.task = info.task;
    curve.trainee = info.trainee;
    Attempt a{info.id, info.started_at, info.station, info.score, info.passed, info.duration_s, time_to_target(s)};
    curve.attempts.push_back(a);
    if (curve.attempts.size() == 1) curve.first_pass = info.passed;
    if (info.passed && curve.attempts_to_pass == 0) curve.attempts_to_pass = int(curve.attempts.size());
    for (const StepResult& step : s.steps) {
      StepFailures& f = failures[{info.task, step.id}];
      f.task = info.task;
      f.step = step.id;
      ++f.attempts;
      f.failed += step.record.outcome != StepOutcome::kCompleted;
    }
    values[{info.task, "score"}].push_back(info.score);
    if (!std::isnan(a.time_to_target_s)) values[{info.task, "time_to_target_s"}].push_back(a.time_to_target_s);
    for_each_metric(s.overall, [&](const char* name, const auto& value) {
      if (!std::isnan(double(value))) values[{info.task, name}].push_back(double(value));
    });
  }
  for (auto& [key, curve] : curves) view.curves.push_back(std::move(curve));
  for (auto& [key, f] : failures)
    if (f.failed > 0) view.most_failed.push_back(f);
  std::stable_sort(view.most_failed.begin(), view.most_failed.end(), [](const StepFailures& a, const StepFailures& b) {
    if (a.failed != b.failed) return a.failed > b.failed;
    return a.failed * b.attempts > b.failed * a.attempts;
  });
  std::vector<std::string> tasks;
  for (const LearningCurve& c : view.curves)
    if (tasks.empty() || tasks.back() != c.task) tasks.push_back(c.task);
  // The layered tissue's metrics apply to a task on layers: there every insertion
  // punctures the skin. A task none of whose sessions punctured anything (the thesis's spheres)
  // gets no rows for them rather than rows of zeros.
  for (const std::string& task : tasks) {
    const std::vector<double>& p = values[{task, "punctures"}];
    if (std::any_of(p.begin(), p.end(), [](double v) { return v > 0.0; })) continue;
    for (const char* metric :
         {"punctures", "overshoot_m", "bone_contacts", "bone_peak_force_N", "redirections", "forbidden_punctures"})
      values[{task, metric}].clear();
  }
  for (const std::string& task : tasks)
    for (const std::string& metric : metric_order) {
      const std::vector<double>& v = values[{task, metric}];
      view.percentiles.push_back({task, metric, v.size(), percentile(v, 10), percentile(v, 25), percentile(v, 50),
                                  percentile(v, 75), percentile(v, 90)});
    }
  return view;
}

}  // namespace needle::training
