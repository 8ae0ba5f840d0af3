#include "app/cohort_report.hpp"

#include <set>

#include "app/default_db.hpp"
#include "app/task_session.hpp"
#include "engine/gpu_device.hpp"
#include "training/sessions/cohort_export.hpp"
#include "training/sessions/cohort_plot.hpp"
#include "ui/cohort_panel.hpp"
#include "ui/panel_picture.hpp"
#include "ui/review_window_frame.hpp"

namespace needle::app {

int write_cohort_report(const std::string& db, const training::CohortFilter& filter, const std::filesystem::path& out,
                        const Messages& messages) {
  const std::unique_ptr<training::SessionStore> store = open_existing_db(db);
  const training::CohortView view = training::cohort_view(*store, filter);
  training::export_cohort(view, out);
  messages.say(formatted("%zu complete sessions, %zu learning curves: wrote %s and its CSV tables", view.sessions,
                         view.curves.size(), (out / "cohort.json").c_str()));
  std::set<std::string> tasks;
  for (const training::LearningCurve& c : view.curves) tasks.insert(c.task);
  if (tasks.empty()) return 0;
  engine::GpuDevice device;
  const engine::Extent size{900, 360};
  for (const std::string& task : tasks)
    for (const bool time_to_target : {false, true}) {
      const training::Plot plot = training::learning_curve_plot(view, task, time_to_target);
      const std::filesystem::path file =
          out / ("cohort_" + file_name_part(task) + (time_to_target ? "_time_to_target.png" : "_score.png"));
      engine::write_png(file, ui::panel_picture(device, size, [&] {
                          ui::draw_learning_curve_window(plot, ui::rect(0, 0, float(size.width), float(size.height)));
                        }));
      messages.say("wrote " + file.string());
    }
  return 0;
}

}  // namespace needle::app
