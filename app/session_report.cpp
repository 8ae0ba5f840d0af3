#include "app/session_report.hpp"

#include <algorithm>
#include <cstdio>

#include "app/default_db.hpp"
#include "app/replay_cursor.hpp"
#include "engine/gpu_device.hpp"
#include "training/sessions/session_export.hpp"
#include "ui/panel_picture.hpp"
#include "ui/review_panels.hpp"
#include "ui/review_replay.hpp"

namespace needle::app {
namespace {

namespace fs = std::filesystem;

void write_picture(const fs::path& file, const engine::RgbaImage& image) {
  engine::write_png(file, image);
  std::printf("wrote %s\n", file.c_str());
}

ui::PanelRect whole(engine::Extent e) { return {ImVec2(0, 0), ImVec2(float(e.width), float(e.height))}; }

}  // namespace

int write_session_report(const fs::path& db, int64_t id, const fs::path& out, std::optional<double> at,
                         ui::TimeSpan plots) {
  const std::unique_ptr<training::SessionStore> store = open_existing_db(db.string());
  const training::SessionReview review = training::load_session_review(*store, db, id);
  const training::SessionInfo& info = review.stored.info;
  if (plots.chosen() && review.has_recording()) {  // checked before anything is written
    if (plots.hi < review.start_s() || plots.lo > review.end_s()) {
      std::fprintf(stderr, "needle-sim report: the plots' range %g to %g s lies outside the recording (%.3f to %.3f s)\n",
                   plots.lo, plots.hi, review.start_s(), review.end_s());
      return 1;
    }
    plots = ui::clamped({std::max(plots.lo, review.start_s()), std::min(plots.hi, review.end_s())},
                        {review.start_s(), review.end_s()});
    std::printf("plots from %.3f to %.3f s\n", plots.lo, plots.hi);
  }
  const fs::path json = training::export_session(review.stored, out, review.punctures());
  std::printf("wrote %s and %s\n", json.c_str(), fs::path(json).replace_extension(".csv").c_str());
  if (!info.complete) {
    std::printf("session %lld is incomplete (its run ended before the task did, or is still going): exported what is "
                "stored, with no score, step results or metrics\n",
                static_cast<long long>(id));
  }

  engine::GpuDevice device;
  ui::SessionTableState table;
  table.selected = id;
  const std::vector<training::SessionInfo> sessions = store->sessions();
  // A layered session's detail has six more metric rows and the force–depth plot.
  const engine::Extent table_size{960, 360}, detail_size{820, review.layered() ? 1640u : 1380u}, plot_size{900, 320},
      replay_size{1280, 720};
  write_picture(out / "review_table.png", ui::panel_picture(device, table_size, [&] {
                  ui::draw_session_table(sessions, table, whole(table_size));
                }));
  const double t = std::clamp(at.value_or(review.end_s()), review.start_s(), review.end_s());
  write_picture(out / "review_detail.png", ui::panel_picture(device, detail_size, [&] {
                  ui::DetailOptions options{t, false, "", plots.chosen() ? &plots : nullptr};
                  ui::draw_session_detail(review, options, whole(detail_size));
                }));
  if (!review.has_recording()) {
    // Sessions stored before runs kept recordings have none: not an error. A named one that
    // cannot be read is.
    std::printf("no plots and no replay picture: %s\n", review.recording_problem.c_str());
    if (info.recording_path.empty()) return 0;
    std::fprintf(stderr, "needle-sim report: %s\n", review.recording_problem.c_str());
    return 1;
  }
  for (const std::string& note : review.recording_notes) std::printf("note: %s\n", note.c_str());
  std::printf("%s\n", training::describe(review.loop).c_str());
  const char* const names[] = {"plot_force.png", "plot_lateral_load.png", "plot_depth.png", "plot_tracking_error.png"};
  const std::vector<const training::Plot*> all = review.plots.all();
  for (size_t k = 0; k < all.size(); ++k) {
    if (all[k]->lines.empty()) {
      std::printf("no %s: %s\n", names[k], all[k]->missing.c_str());
      continue;
    }
    write_picture(out / names[k], ui::panel_picture(device, plot_size, [&] {
                    ui::draw_plot_window(review, *all[k], whole(plot_size), plots);
                  }));
  }
  if (review.layered()) {
    if (review.force_depth.plot.lines.empty())
      std::printf("no plot_force_depth.png: %s\n", review.force_depth.plot.missing.c_str());
    else
      write_picture(out / "plot_force_depth.png", ui::panel_picture(device, plot_size, [&] {
                      ui::draw_force_depth_window(review.force_depth, nullptr, whole(plot_size));
                    }));
    std::printf("%zu puncture(s)\n", review.force_depth.puncture_list.size());
  }
  if (!review.task) {
    std::printf("no replay picture: %s\n", review.task_problem.c_str());
    return 0;
  }
  ReplayCursor cursor(tissue_kind(*review.task));
  ui::PictureScene scene{engine::load_scene(review.task->scene), cursor.at(review.states, t), 0.0f};
  double shown_t = t;
  const ui::PanelRect bar{ImVec2(0, float(replay_size.height) - 64.0f), ImVec2(float(replay_size.width), 64.0f)};
  write_picture(out / "review_replay.png", ui::panel_picture(device, replay_size, [&] {
                  ui::draw_replay_bar(review, shown_t, false, bar);
                }, &scene, 4));
  return 0;
}

}  // namespace needle::app
