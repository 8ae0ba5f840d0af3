#include "app/session_report.hpp"

#include <algorithm>

#include "app/default_db.hpp"
#include "app/replay_cursor.hpp"
#include "engine/gpu_device.hpp"
#include "training/sessions/session_export.hpp"
#include "ui/panel_picture.hpp"
#include "ui/review_panels.hpp"
#include "ui/review_replay.hpp"
#include "ui/review_window_frame.hpp"

namespace needle::app {
namespace {

namespace fs = std::filesystem;

void write_picture(const fs::path& file, const engine::RgbaImage& image, const Messages& messages) {
  engine::write_png(file, image);
  messages.say("wrote " + file.string());
}

ui::PanelRect whole(engine::Extent e) { return ui::rect(0, 0, float(e.width), float(e.height)); }

}  // namespace

int write_session_report(const fs::path& db, int64_t id, const fs::path& out, std::optional<double> at,
                         ui::TimeSpan plots, const Messages& messages) {
  const std::unique_ptr<training::SessionStore> store = open_existing_db(db.string());
  const training::SessionReview review = training::load_session_review(*store, db, id);
  const training::SessionInfo& info = review.stored.info;
  if (plots.chosen() && review.has_recording()) {  // checked before anything is written
    if (plots.hi < review.start_s() || plots.lo > review.end_s()) {
      messages.warn(formatted("the plots' range %g to %g s lies outside the recording (%.3f to %.3f s)", plots.lo,
                              plots.hi, review.start_s(), review.end_s()));
      return 1;
    }
    plots = ui::clamped({std::max(plots.lo, review.start_s()), std::min(plots.hi, review.end_s())},
                        {review.start_s(), review.end_s()});
    messages.say(formatted("plots from %.3f to %.3f s", plots.lo, plots.hi));
  }
  const fs::path json = training::export_session(review.stored, out, review.punctures());
  messages.say("wrote " + json.string() + " and " + fs::path(json).replace_extension(".csv").string());
  if (!info.complete) {
    messages.say(
        formatted("session %lld is incomplete (its run ended before the task did, or is still going): exported "
                  "what is stored, with no score, step results or metrics",
                  static_cast<long long>(id)));
  }

  engine::GpuDevice device;
  ui::SessionTableState table;
  table.selected = id;
  const std::vector<training::SessionInfo> sessions = store->sessions();
  // A layered session's detail has six more metric rows and the force–depth plot.
  const engine::Extent table_size{960, 360}, detail_size{820, review.layered() ? 1640u : 1380u}, plot_size{900, 320},
      replay_size{1280, 720};
  write_picture(
      out / "review_table.png",
      ui::panel_picture(device, table_size, [&] { ui::draw_session_table(sessions, table, whole(table_size)); }),
      messages);
  const double t = std::clamp(at.value_or(review.end_s()), review.start_s(), review.end_s());
  write_picture(out / "review_detail.png",
                ui::panel_picture(device, detail_size,
                                  [&] {
                                    ui::DetailOptions options{t, false, "", plots.chosen() ? &plots : nullptr};
                                    ui::draw_session_detail(review, options, whole(detail_size));
                                  }),
                messages);
  if (!review.has_recording()) {
    // Sessions stored before runs kept recordings have none: not an error. A named one that
    // cannot be read is.
    messages.say("no plots and no replay picture: " + review.recording_problem);
    if (info.recording_path.empty()) return 0;
    messages.warn(review.recording_problem);
    return 1;
  }
  for (const std::string& note : review.recording_notes) messages.say("note: " + note);
  messages.say(training::describe(review.loop));
  const char* const names[] = {"plot_force.png", "plot_lateral_load.png", "plot_depth.png", "plot_tracking_error.png"};
  const std::vector<const training::Plot*> all = review.plots.all();
  for (size_t k = 0; k < all.size(); ++k) {
    if (all[k]->lines.empty()) {
      messages.say(std::string("no ") + names[k] + ": " + all[k]->missing);
      continue;
    }
    write_picture(
        out / names[k],
        ui::panel_picture(device, plot_size, [&] { ui::draw_plot_window(review, *all[k], whole(plot_size), plots); }),
        messages);
  }
  // A plot against depth, or why there is none.
  const auto depth_plot = [&](const char* file, const training::Plot& plot, auto draw_window) {
    if (plot.lines.empty())
      messages.say(std::string("no ") + file + ": " + plot.missing);
    else
      write_picture(
          out / file,
          ui::panel_picture(device, plot_size, [&] { draw_window(review.force_depth, nullptr, whole(plot_size)); }),
          messages);
  };
  if (review.layered()) {
    depth_plot("plot_force_depth.png", review.force_depth.plot, ui::draw_force_depth_window);
    messages.say(formatted("%zu puncture(s)", review.force_depth.puncture_list.size()));
  }
  if (review.has_syringe()) {
    depth_plot("plot_plunger_pressure.png", review.force_depth.pressure, ui::draw_plunger_pressure_window);
    messages.say(formatted("%zu loss(es) of resistance", review.force_depth.losses.size()));
  }
  if (!review.task) {
    messages.say("no replay picture: " + review.task_problem);
    return 0;
  }
  ReplayCursor cursor(tissue_kind(*review.task));
  ui::PictureScene scene{engine::load_scene(review.task->scene), cursor.at(review.states, t), 0.0f};
  double shown_t = t;
  const ui::PanelRect bar = ui::rect(0, float(replay_size.height) - 64.0f, float(replay_size.width), 64.0f);
  write_picture(out / "review_replay.png",
                ui::panel_picture(
                    device, replay_size, [&] { ui::draw_replay_bar(review, shown_t, false, bar); }, &scene, 4),
                messages);
  return 0;
}

}  // namespace needle::app
