#include "training/scoring/score.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace needle::training {

namespace {

double clamp01(double x) { return std::clamp(x, 0.0, 1.0); }

// 1 at zero, falling linearly to 0 at the reference; 1 when the metric does not apply.
double falling(double value, double reference) { return std::isnan(value) ? 1.0 : clamp01(1.0 - value / reference); }

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

// Smoothness on a log scale (normalized jerk spans orders of magnitude): 1 at the minimum-jerk
// profile's sqrt(360), 0 at the reference.
double smoothness(double normalized_jerk, double reference) {
  if (std::isnan(normalized_jerk)) return 1.0;
  const double minimum = std::sqrt(360.0);
  return clamp01(1.0 - std::log(std::max(normalized_jerk, minimum) / minimum) / std::log(reference / minimum));
}

}  // namespace

Metrics combine_metrics(const std::vector<StepResult>& steps) {
  Metrics m;
  for (const StepResult& s : steps) {
    const Metrics& x = s.metrics;
    m.duration_s += x.duration_s;
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
    // The syringe's: counts and times add up (not applicable when no step has them), the loss's are the step's that had it.
    for (auto [total, step] : {std::pair{&m.false_losses, x.false_losses}, std::pair{&m.pressure_applied_s, x.pressure_applied_s}})
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

Score score_session(const ScoringSpec& spec, const std::vector<StepResult>& steps, const Metrics& m) {
  const ScoreWeights& w = spec.weights;
  const ScoreReferences& r = spec.references;
  const long completed = std::count_if(steps.begin(), steps.end(),
                                       [](const StepResult& s) { return s.record.outcome == StepOutcome::kCompleted; });
  const double peak = m.peak_hand_force_N, safe = spec.safe_force_N;
  Score score;
  score.components = {
      {"completion", steps.empty() ? 0.0 : double(completed) / double(steps.size()), w.completion},
      {"tip_error", falling(m.tip_error_m, r.tip_error_m), w.tip_error},
      {"axis_deviation", falling(m.axis_deviation_deg, r.axis_deviation_deg), w.axis_deviation},
      {"lateral_load", falling(m.lateral_load_Ns, r.lateral_load_Ns), w.lateral_load},
      {"peak_force", peak <= safe ? 1.0 : clamp01(1.0 - (peak - safe) / safe), w.peak_force},
      {"force_steadiness", falling(m.force_sd_N, r.force_sd_N), w.force_steadiness},
      {"path_efficiency", m.path_length_m > 0.0 ? clamp01(m.ideal_path_m / m.path_length_m) : 1.0, w.path_efficiency},
      {"smoothness", smoothness(m.normalized_jerk, r.normalized_jerk), w.smoothness},
      {"time", m.duration_s <= r.time_s ? 1.0 : r.time_s / m.duration_s, w.time},
      {"retries", 1.0 / (1.0 + m.reinsertions + m.rigid_contacts), w.retries},
  };
  // Only a task with an ultrasound probe weighs the needle's visibility (docs/SCORING.md).
  if (w.needle_visibility > 0.0)
    score.components.push_back({"needle_visibility", std::isnan(m.needle_visibility) ? 1.0 : m.needle_visibility,
                                w.needle_visibility});
  // Only a task on a layered tissue weighs the technique through its layers (docs/SCORING.md).
  if (w.overshoot > 0.0) score.components.push_back({"overshoot", falling(m.overshoot_m, r.overshoot_m), w.overshoot});
  if (w.bone_contacts > 0.0) score.components.push_back({"bone_contacts", 1.0 / (1.0 + m.bone_contacts), w.bone_contacts});
  if (w.redirections > 0.0) score.components.push_back({"redirections", 1.0 / (1.0 + m.redirections), w.redirections});
  // Only a task with a syringe weighs the loss of resistance: how little the tip went on after it, less
  // for every false loss; nothing when no loss was found (docs/SCORING.md, "Syringe").
  if (w.loss_of_resistance > 0.0) {
    const double stop = std::isnan(m.advance_after_loss_m) ? 0.0 : falling(m.advance_after_loss_m, r.loss_advance_m);
    const double false_losses = std::isnan(m.false_losses) ? 0.0 : m.false_losses;
    score.components.push_back({"loss_of_resistance", stop / (1.0 + false_losses), w.loss_of_resistance});
  }
  for (const ScoreComponent& c : score.components) score.total += c.points();
  if (score.total < spec.pass_score)
    score.reasons_failed.push_back("score " + format(score.total) + " below the pass mark " + format(spec.pass_score));
  if (completed < long(steps.size()))
    score.reasons_failed.push_back(std::to_string(steps.size() - completed) + " step(s) not completed");
  // A forbidden layer (the dura) or bone touched fails the task whatever the rest (issue 14).
  for (const StepResult& s : steps)
    if (s.record.outcome == StepOutcome::kForbiddenPuncture || s.record.outcome == StepOutcome::kRigidTouched ||
        s.record.outcome == StepOutcome::kAdvancedPastLoss)
      score.reasons_failed.push_back("step " + s.id + ": " + (s.failure.empty() ? step_outcome_name(s.record.outcome) : s.failure));
  if (m.faults > 0) score.reasons_failed.push_back(std::to_string(m.faults) + " safety fault(s)");
  if (peak > safe)
    score.reasons_failed.push_back("peak force at the hand " + format(peak) + " N above the safe limit " + format(safe) + " N");
  score.passed = score.reasons_failed.empty();
  return score;
}

}  // namespace needle::training
