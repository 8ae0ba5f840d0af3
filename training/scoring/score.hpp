// The overall score 0-100 from a session's metrics: a weighted sum of components in [0, 1]
// (weights and references from the task's scoring block; docs/SCORING.md).
#pragma once

#include <string>
#include <vector>

#include "training/scoring/metrics.hpp"
#include "training/tasks/task.hpp"
#include "training/tasks/task_progress.hpp"

namespace needle::training {

// Whether a component counted (docs/SCORING.md, "Score"): it applied; the run never reached what it
// measures (no points, its weight kept: the task asked for it); the task does not measure it (no
// weight: the components it measures share the task's 100 points).
enum class ComponentStatus { kApplied, kNotReached, kNotApplicable };
const char* component_status_name(ComponentStatus status);  // "applied", "not_reached", "not_applicable"

struct ScoreComponent {
  std::string name;     // "completion", "tip_error", ... (the ScoreWeights names)
  double value = 0.0;   // in [0, 1]; 0 unless it applied
  double weight = 0.0;  // points it is worth (the weights add up to 100); 0 when not applicable
  ComponentStatus status = ComponentStatus::kApplied;
  double points() const { return value * weight; }
};

struct Score {
  double total = 0.0;  // 0-100
  bool passed = false;
  std::vector<ScoreComponent> components;
  std::vector<std::string> reasons_failed;  // empty when passed
};

struct StepResult {
  std::string id;
  StepRecord record;
  Metrics metrics;
  std::string failure = {};  // step_failure_reason of a step that did not complete, when scored live
};

// Whether the run reached what the component `name` measures, from the session's metrics
// (docs/SCORING.md, "Score"): e.g. lateral_load once the needle was in tissue, overshoot once a
// membrane gave way, time once every step was completed. completion is always reached.
bool component_reached(const std::string& name, const Metrics& overall, bool every_step_completed);
long completed_steps(const std::vector<StepResult>& steps);

// Smoothness on a log scale (normalized jerk spans orders of magnitude): 1 at the minimum-jerk
// profile's sqrt(360), 0 at `reference`; 0 when it does not apply (NaN).
double smoothness_score(double normalized_jerk, double reference);

// `overall` is the session's metrics (combine_metrics of the steps).
Score score_session(const ScoringSpec& spec, const std::vector<StepResult>& steps, const Metrics& overall);

// Session metrics from the steps' (docs/SCORING.md, "overall").
Metrics combine_metrics(const std::vector<StepResult>& steps);

}  // namespace needle::training
