#include "app/cohort_report.hpp"

#include <cmath>
#include <cstdio>
#include <set>

#include "app/default_db.hpp"
#include "app/task_session.hpp"
#include "engine/gpu_device.hpp"
#include "training/sessions/cohort_export.hpp"
#include "ui/panel_picture.hpp"
#include "ui/review_panels.hpp"

namespace needle::app {

training::Plot learning_curve_plot(const training::CohortView& view, const std::string& task, bool time_to_target) {
  training::Plot plot;
  plot.title = (time_to_target ? "Time to target over attempts: " : "Score over attempts: ") + task;
  plot.unit = time_to_target ? "s" : "points";
  plot.x_label = "attempt";
  for (const training::LearningCurve& c : view.curves) {
    if (c.task != task) continue;
    training::Series line{c.trainee, {}, {}};
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

int write_cohort_report(const std::string& db, const training::CohortFilter& filter, const std::filesystem::path& out) {
  const std::unique_ptr<training::SessionStore> store = open_existing_db(db);
  const training::CohortView view = training::cohort_view(*store, filter);
  training::export_cohort(view, out);
  std::printf("%zu complete sessions, %zu learning curves: wrote %s and its CSV tables\n", view.sessions, view.curves.size(),
              (out / "cohort.json").c_str());
  std::set<std::string> tasks;
  for (const training::LearningCurve& c : view.curves) tasks.insert(c.task);
  if (tasks.empty()) return 0;
  engine::GpuDevice device;
  const engine::Extent size{900, 360};
  for (const std::string& task : tasks)
    for (const bool time_to_target : {false, true}) {
      const training::Plot plot = learning_curve_plot(view, task, time_to_target);
      const std::filesystem::path file =
          out / ("cohort_" + file_name_part(task) + (time_to_target ? "_time_to_target.png" : "_score.png"));
      engine::write_png(file, ui::panel_picture(device, size, [&] {
                          ui::draw_plot_window(plot, nullptr, {ImVec2(0, 0), ImVec2(float(size.width), float(size.height))});
                        }));
      std::printf("wrote %s\n", file.c_str());
    }
  return 0;
}

}  // namespace needle::app
