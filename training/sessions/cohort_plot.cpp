#include "training/sessions/cohort_plot.hpp"

#include <cmath>

namespace needle::training {

Plot learning_curve_plot(const CohortView& view, const std::string& task, bool time_to_target) {
  Plot plot;
  plot.title = (time_to_target ? "Time to target over attempts: " : "Score over attempts: ") + task;
  plot.unit = time_to_target ? "s" : "points";
  plot.x_label = "attempt";
  for (const LearningCurve& c : view.curves) {
    if (c.task != task) continue;
    Series line{c.trainee, {}, {}};
    for (size_t k = 0; k < c.attempts.size(); ++k) {
      const double v = time_to_target ? c.attempts[k].time_to_target_s : c.attempts[k].score;
      if (std::isnan(v)) continue;
      line.t.push_back(double(k + 1));
      line.v.push_back(v);
    }
    if (!line.t.empty()) plot.lines.push_back(std::move(line));
  }
  if (plot.lines.empty()) plot.missing = time_to_target ? "no attempt reached a target" : "no attempts";
  return plot;
}

}  // namespace needle::training
