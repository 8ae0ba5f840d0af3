#include "training/scoring/score.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace needle::training {

namespace {

double clamp01(double x) { return std::clamp(x, 0.0, 1.0); }

// 1 at zero, falling linearly to 0 at the reference (a metric that does not apply scores nothing).
double falling(double value, double reference) { return std::isnan(value) ? 0.0 : clamp01(1.0 - value / reference); }

// Mean of the applicable (non-NaN) values; NaN when none.
template <class Get>
double mean_applicable(const std::vector<StepResult>& steps, Get get) {
  double sum = 0.0;
  int n = 0;
  for (const StepResult& s : steps)
    if (const double v = get(s.metrics); !std::isnan(v)) sum += v, ++n;
  return n ? sum / n : kNotApplicable;
}

std::string format(double x) {
  std::ostringstream out;
  out.precision(3);
  out << x;
  return out.str();
}

}  // namespace

Metrics combine_metrics(const std::vector<StepResult>& steps) {
  Metrics m;
  for (const StepResult& s : steps) {
    const Metrics& x = s.metrics;
    m.duration_s += x.duration_s;
    m.tissue_time_s += x.tissue_time_s;
    m.lateral_load_Ns += x.lateral_load_Ns;
    m.lateral_peak_N = std::max(m.lateral_peak_N, x.lateral_peak_N);
    m.peak_force_N = std::max(m.peak_force_N, x.peak_force_N);
    m.peak_axial_force_N = std::max(m.peak_axial_force_N, x.peak_axial_force_N);
    m.peak_needle_force_N = std::max(m.peak_needle_force_N, x.peak_needle_force_N);
    m.peak_hand_force_N = std::max(m.peak_hand_force_N, x.peak_hand_force_N);
    m.force_limited_s += x.force_limited_s;
    m.passivity_damped_s += x.passivity_damped_s;
    m.path_length_m += x.path_length_m;
    m.ideal_path_m += x.ideal_path_m;
    m.withdrawals += x.withdrawals;
    m.reinsertions += x.reinsertions;
    m.rigid_contacts += x.rigid_contacts;
    m.punctures += x.punctures;
    if (!std::isnan(x.overshoot_m)) m.overshoot_m = x.overshoot_m;  // the last step's that had one
    m.bone_contacts += x.bone_contacts;
    m.bone_peak_force_N = std::max(m.bone_peak_force_N, x.bone_peak_force_N);
    m.redirections += x.redirections;
    m.forbidden_punctures += x.forbidden_punctures;
    // The syringe's: counts and times add up (not applicable when no step has them), the loss's are the step's that had
    // it.
    for (auto [total, step] :
         {std::pair{&m.false_losses, x.false_losses}, std::pair{&m.pressure_applied_s, x.pressure_applied_s}})
      if (!std::isnan(step)) *total = (std::isnan(*total) ? 0.0 : *total) + step;
    for (auto [last, step] : {std::pair{&m.advance_after_loss_m, x.advance_after_loss_m},
                              std::pair{&m.loss_pressure_before_Pa, x.loss_pressure_before_Pa},
                              std::pair{&m.loss_pressure_after_Pa, x.loss_pressure_after_Pa}})
      if (!std::isnan(step)) *last = step;
    if (m.faults == 0) m.first_fault = x.first_fault;
    m.faults += x.faults;
  }
  m.tip_error_m = mean_applicable(steps, [](const Metrics& x) { return x.tip_error_m; });
  m.axis_deviation_deg = mean_applicable(steps, [](const Metrics& x) { return x.axis_deviation_deg; });
  m.force_sd_N = mean_applicable(steps, [](const Metrics& x) { return x.force_sd_N; });
  m.normalized_jerk = mean_applicable(steps, [](const Metrics& x) { return x.normalized_jerk; });
  m.needle_visibility = mean_applicable(steps, [](const Metrics& x) { return x.needle_visibility; });
  return m;
}

long completed_steps(const std::vector<StepResult>& steps) {
  return std::count_if(steps.begin(), steps.end(),
                       [](const StepResult& s) { return s.record.outcome == StepOutcome::kCompleted; });
}

bool component_reached(const std::string& name, const Metrics& m, bool every_step_completed) {
  const bool touched = m.peak_needle_force_N > 0.0 || m.tissue_time_s > 0.0;  // the world pushed on the needle
  const bool punctured = m.punctures > 0;
  if (name == "tip_error") return !std::isnan(m.tip_error_m);
  if (name == "axis_deviation") return !std::isnan(m.axis_deviation_deg);
  if (name == "lateral_load") return m.tissue_time_s > 0.0;
  if (name == "peak_force" || name == "retries") return touched;
  if (name == "force_steadiness") return !std::isnan(m.force_sd_N);
  if (name == "path_efficiency") return m.path_length_m > 0.0;
  if (name == "smoothness") return !std::isnan(m.normalized_jerk);
  if (name == "time") return every_step_completed;
  if (name == "needle_visibility") return !std::isnan(m.needle_visibility);
  if (name == "overshoot") return !std::isnan(m.overshoot_m);
  if (name == "bone_contacts") return punctured || m.bone_contacts > 0;
  if (name == "redirections") return punctured || m.redirections > 0;
  if (name == "loss_of_resistance")
    return !std::isnan(m.advance_after_loss_m);  // a loss was found in the syringe's space
  return true;                                   // completion
}

double smoothness_score(double normalized_jerk, double reference) {
  if (std::isnan(normalized_jerk)) return 0.0;
  const double minimum = std::sqrt(360.0);
  return clamp01(1.0 - std::log(std::max(normalized_jerk, minimum) / minimum) / std::log(reference / minimum));
}

const char* component_status_name(ComponentStatus status) {
  switch (status) {
    case ComponentStatus::kApplied:
      return "applied";
    case ComponentStatus::kNotReached:
      return "not_reached";
    case ComponentStatus::kNotApplicable:
      return "not_applicable";
  }
  return "applied";
}

Score score_session(const ScoringSpec& spec, const std::vector<StepResult>& steps, const Metrics& m) {
  const ScoreWeights& w = spec.weights;
  const ScoreReferences& r = spec.references;
  const ScoreMeasures& task = spec.measures;
  const long completed = completed_steps(steps);
  const double peak = m.peak_hand_force_N, safe = spec.safe_force_N;
  // name, value, weight, whether the task measures it.
  struct Part {
    const char* name;
    double value, weight;
    bool measured;
  };
  std::vector<Part> parts = {
      {"completion", steps.empty() ? 0.0 : double(completed) / double(steps.size()), w.completion, true},
      {"tip_error", falling(m.tip_error_m, r.tip_error_m), w.tip_error, task.tip_error},
      {"axis_deviation", falling(m.axis_deviation_deg, r.axis_deviation_deg), w.axis_deviation, task.axis_deviation},
      {"lateral_load", falling(m.lateral_load_Ns, r.lateral_load_Ns), w.lateral_load, task.lateral_load},
      {"peak_force", peak <= safe ? 1.0 : clamp01(1.0 - (peak - safe) / safe), w.peak_force, true},
      {"force_steadiness", falling(m.force_sd_N, r.force_sd_N), w.force_steadiness, task.force_steadiness},
      {"path_efficiency", m.path_length_m > 0.0 ? clamp01(m.ideal_path_m / m.path_length_m) : 0.0, w.path_efficiency,
       true},
      {"smoothness", smoothness_score(m.normalized_jerk, r.normalized_jerk), w.smoothness, true},
      {"time", m.duration_s <= r.time_s ? 1.0 : r.time_s / m.duration_s, w.time, true},
      {"retries", 1.0 / (1.0 + m.reinsertions + m.rigid_contacts), w.retries, true},
  };
  // Only a task with an ultrasound probe weighs the needle's visibility, only a task on a layered
  // tissue the technique through its layers (their weights are 0 otherwise; docs/SCORING.md).
  if (w.needle_visibility > 0.0)
    parts.push_back(
        {"needle_visibility", std::isnan(m.needle_visibility) ? 0.0 : m.needle_visibility, w.needle_visibility, true});
  if (w.overshoot > 0.0) parts.push_back({"overshoot", falling(m.overshoot_m, r.overshoot_m), w.overshoot, true});
  if (w.bone_contacts > 0.0) parts.push_back({"bone_contacts", 1.0 / (1.0 + m.bone_contacts), w.bone_contacts, true});
  if (w.redirections > 0.0) parts.push_back({"redirections", 1.0 / (1.0 + m.redirections), w.redirections, true});
  // Only a task with a syringe weighs the loss of resistance: how little the tip went on after it, less
  // for every false loss (docs/SCORING.md, "Syringe"); not reached when no loss was found.
  if (w.loss_of_resistance > 0.0) {
    const double false_losses = std::isnan(m.false_losses) ? 0.0 : m.false_losses;
    parts.push_back({"loss_of_resistance", falling(m.advance_after_loss_m, r.loss_advance_m) / (1.0 + false_losses),
                     w.loss_of_resistance, true});
  }
  // The task's weights over the components it measures, renormalised to 100.
  double measured_weight = 0.0;
  for (const Part& p : parts)
    if (p.measured) measured_weight += p.weight;
  Score score;
  for (const Part& p : parts) {
    ScoreComponent c{p.name, 0.0, 0.0, ComponentStatus::kNotApplicable};
    if (p.measured && p.weight > 0.0) {  // then measured_weight > 0
      const bool reached = component_reached(p.name, m, !steps.empty() && completed == long(steps.size()));
      c.weight = p.weight * 100.0 / measured_weight;
      c.status = reached ? ComponentStatus::kApplied : ComponentStatus::kNotReached;
      if (reached) c.value = p.value;
    }
    score.components.push_back(c);
  }
  for (const ScoreComponent& c : score.components) score.total += c.points();
  if (score.total < spec.pass_score)
    score.reasons_failed.push_back("score " + format(score.total) + " below the pass mark " + format(spec.pass_score));
  if (completed < long(steps.size()))
    score.reasons_failed.push_back(std::to_string(steps.size() - completed) + " step(s) not completed");
  // A forbidden layer (the dura) or bone touched fails the task whatever the rest.
  for (const StepResult& s : steps)
    if (s.record.outcome == StepOutcome::kForbiddenPuncture || s.record.outcome == StepOutcome::kRigidTouched ||
        s.record.outcome == StepOutcome::kAdvancedPastLoss)
      score.reasons_failed.push_back("step " + s.id + ": " +
                                     (s.failure.empty() ? step_outcome_name(s.record.outcome) : s.failure));
  if (m.faults > 0) score.reasons_failed.push_back(std::to_string(m.faults) + " safety fault(s)");
  if (peak > safe)
    score.reasons_failed.push_back("peak force at the hand " + format(peak) + " N above the safe limit " +
                                   format(safe) + " N");
  score.passed = score.reasons_failed.empty();
  return score;
}

}  // namespace needle::training
