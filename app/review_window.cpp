#include "app/review_window.hpp"

#include <algorithm>
#include <chrono>
#include <memory>

#include "app/default_db.hpp"
#include "app/echo_scene.hpp"
#include "app/replay_cursor.hpp"
#include "app/ultrasound_window.hpp"
#include "app/window_frames.hpp"
#include "engine/gpu_scene.hpp"
#include "engine/ui_pass.hpp"
#include "training/sessions/cohort_export.hpp"
#include "training/sessions/session_export.hpp"
#include "ui/cohort_panel.hpp"
#include "ui/input_focus.hpp"
#include "ui/review_panels.hpp"
#include "ui/review_replay.hpp"
#include "ui/review_window_frame.hpp"
#include "ui/status_panel.hpp"

namespace needle::app {
namespace {

namespace fs = std::filesystem;

// The part of the window's width the table and the detail take; the 3D view is right of it.
constexpr float kPanelsFraction = 0.46f;
constexpr auto kRefresh = std::chrono::seconds(2);

// A session to show, loaded when the table's choice changes; the error when it cannot be read.
struct Loaded {
  std::optional<training::SessionReview> review;
  std::string error;
  int64_t id = 0;
  bool complete = false;

  // Loads `id` when it is not the one held, or when it has been completed since.
  bool update(const training::SessionStore& store, const fs::path& db, int64_t wanted,
              const std::vector<training::SessionInfo>& list) {
    bool now_complete = false;
    for (const training::SessionInfo& s : list) now_complete |= s.id == wanted && s.complete;
    if (wanted == id && now_complete == complete) return false;
    id = wanted;
    complete = now_complete;
    review.reset();
    error.clear();
    if (wanted == 0) return true;
    try {
      review = training::load_session_review(store, db, wanted);
    } catch (const std::exception& e) {
      error = e.what();
    }
    return true;
  }
};

// The rectangle `at` of `image` (clamped to it).
engine::RgbaImage cropped(const engine::RgbaImage& image, const ui::PanelRect& at) {
  const uint32_t x0 = std::min(uint32_t(std::max(at.pos.x, 0.0f)), image.width);
  const uint32_t y0 = std::min(uint32_t(std::max(at.pos.y, 0.0f)), image.height);
  const uint32_t x1 = std::min(uint32_t(std::max(at.pos.x + at.size.x, 0.0f)), image.width);
  const uint32_t y1 = std::min(uint32_t(std::max(at.pos.y + at.size.y, 0.0f)), image.height);
  engine::RgbaImage out{x1 - x0, y1 - y0, {}};
  for (uint32_t y = y0; y < y1; ++y)
    out.pixels.insert(out.pixels.end(), image.at(x0, y), image.at(x0, y) + size_t(x1 - x0) * 4);
  return out;
}

}  // namespace

int run_review_window(const ReviewOptions& options) {
  if (!engine::Window::display_available()) {
    throw std::runtime_error(
        "no display: the review is a window; for a headless export use needle-sim report --session ID --out DIR");
  }
  const std::unique_ptr<training::SessionStore> store = open_existing_db(options.db.string());
  GpuWindow vw("needle-sim review", options.size, options.messages);
  engine::Window& window = vw.window;
  engine::WindowTarget& target = vw.target;
  engine::SceneRenderer renderer(vw.device, target, {vw.default_msaa_samples()});
  auto scene = std::make_unique<engine::GpuScene>(renderer, engine::Model{}, engine::Scene{});
  engine::GpuScene empty_scene(renderer, engine::Model{}, engine::Scene{});  // behind the Class tab
  fs::path scene_file;
  std::string scene_error;
  // The recorded task's ultrasound image at the scrubbed time, in a task with a probe or with
  // layers made to be imaged (the layered tasks: a probe following the needle, as the window's).
  std::unique_ptr<UltrasoundWindow> ultrasound;
  engine::UiPass ui_pass(renderer, &window);
  ui::FrameClock clock;

  ui::SessionTableState table;
  table.selected = options.session;
  std::vector<training::SessionInfo> sessions = store->sessions();
  auto refreshed = std::chrono::steady_clock::now();
  Loaded a, b;
  ReplayCursor cursor;
  double t = 0.0;
  bool playing = false;
  ui::DetailOptions detail;
  detail.show_export = true;
  ui::TimeSpan span;  // the plots' time range, the whole session at first
  detail.span = &span;
  ui::CohortPanel class_view;
  class_view.state.show_export = true;
  bool select_class = options.class_view;
  std::optional<fs::path> class_picture;  // the Class tab's PNG, written from the frame drawn next

  WindowFrames frames(options.frames, options.screenshot, options.messages);
  bool quit = false;  // Quit (Esc), or the window closed
  while (!window.should_close() && !quit) {
    window.poll_events();
    for (const engine::Window::KeyPress& press : window.take_key_presses())
      if (press.key == engine::Key::kEscape && !ui::typing()) quit = true;  // Esc in the filter field leaves the field
    const float dt = clock.tick();
    if (std::chrono::steady_clock::now() - refreshed > kRefresh) {
      sessions = store->sessions();
      refreshed = std::chrono::steady_clock::now();
    }
    if (a.update(*store, options.db, table.selected, sessions)) {
      cursor = ReplayCursor(a.review && a.review->task ? tissue_kind(*a.review->task) : TissueKind::SingleSurface);
      playing = false;
      detail.export_message.clear();
      span = {};
      t = a.review ? a.review->end_s() : 0.0;
      renderer.wait_idle();  // the old ultrasound view's image may still be drawn in flight
      ultrasound.reset();
      if (a.review && a.review->task) {
        try {
          const training::Task& task = *a.review->task;
          if (task.ultrasound_probe || layers_have_acoustics(task))
            ultrasound = std::make_unique<UltrasoundWindow>(vw.device, task);
        } catch (const std::exception& e) {
          options.messages.warn(std::string("no ultrasound replay: ") + e.what());
        }
      }
      const fs::path wanted = a.review && a.review->task ? a.review->task->scene : fs::path();
      if (wanted != scene_file) {
        renderer.wait_idle();  // the old scene's buffers may still be in flight
        scene_file = wanted;
        scene_error.clear();
        try {
          scene = wanted.empty() ? std::make_unique<engine::GpuScene>(renderer, engine::Model{}, engine::Scene{})
                                 : std::make_unique<engine::GpuScene>(renderer, engine::load_scene(wanted));
        } catch (const std::exception& e) {
          scene_error = e.what();
          scene = std::make_unique<engine::GpuScene>(renderer, engine::Model{}, engine::Scene{});
        }
      }
    }
    b.update(*store, options.db, table.compared, sessions);
    if (playing && a.review) {
      t += dt;
      if (t >= a.review->end_s()) t = a.review->end_s(), playing = false;
    }

    const engine::Extent extent = target.extent();
    const float w = float(extent.width), h = float(extent.height), left = kPanelsFraction * w;
    ui_pass.begin_frame(extent, dt);
    const float bar = ui::replay_bar_height();
    const ui::ReviewTabs tabs = ui::draw_review_tabs(left, select_class);
    quit = quit || tabs.quit;
    const bool class_tab = tabs.class_tab;
    const float top = tabs.height;
    const ui::PanelRect class_rect = ui::rect(0, top, w, h - top);
    if (class_tab) {
      class_view.update(*store, sessions);
      if (ui::draw_cohort_panel(class_view.view, class_view.state, class_rect)) {
        const fs::path dir = local_folder(options.db.string()) / "exports" / "cohort";
        try {
          training::export_cohort(class_view.view, dir);
          class_picture = dir / "cohort_view.png";
          class_view.state.export_message =
              "wrote " + (dir / "cohort.json").string() + ", the CSV tables and cohort_view.png";
        } catch (const std::exception& e) {
          class_view.state.export_message = e.what();
        }
      }
    } else {
      ui::draw_session_table(sessions, table, ui::rect(0, top, left, 0.32f * h - top));
      const ui::PanelRect below = ui::rect(0, 0.32f * h, left, 0.68f * h);
      if (a.review) {
        detail.cursor_s = t;
        if (ui::draw_session_detail(*a.review, detail, below)) {
          const fs::path dir = local_folder(options.db.string()) / "exports";
          try {
            detail.export_message = "wrote " +
                                    training::export_session(a.review->stored, dir, a.review->punctures()).string() +
                                    " and the .csv";
          } catch (const std::exception& e) {
            detail.export_message = e.what();
          }
        }
        playing = ui::draw_replay_bar(*a.review, t, playing, ui::rect(left, h - bar, w - left, bar));
        if (!scene_error.empty())
          ui::draw_note("3D view", ui::rect(left + 10.0f, 10.0f, 0, 0), "no replay: " + scene_error);
        if (b.review) {
          bool open = true;
          ui::draw_comparison(*a.review, *b.review, ui::rect(left, 0, w - left, h - bar), &open, &span);
          if (!open) table.compared = 0;
        }
      } else {
        ui::draw_note("Session", below,
                      !a.error.empty()   ? a.error
                      : sessions.empty() ? "The database has no sessions yet: needle-sim run makes them."
                                         : "Click a session to review it; B picks one to compare it with.");
      }
    }
    const bool replaying = !class_tab && a.review && a.review->has_recording() && scene_error.empty() && !b.review;
    const engine::NeedleLoad* needle = replaying ? &cursor.at(a.review->states, t) : nullptr;
    engine::FrameParams params = (class_tab ? empty_scene : *scene).frame_params(needle);
    ui::frame_beside_panels(params.camera, w / h, kPanelsFraction);
    if (needle && ultrasound) {
      ultrasound->place(w - 10.0f, 10.0f, 1.0f, 0.0f);  // the 3D view's top right corner
      ultrasound->draw_panel(*needle, params.camera);
    }
    params.overlay = ui_pass.end_frame();
    if (needle && ultrasound) ultrasound->add_to_frame(params, renderer, extent, *needle);

    frames.draw(window, [&](engine::RgbaImage* shot) {
      engine::RgbaImage picture;
      engine::RgbaImage* capture = shot ? shot : class_picture ? &picture : nullptr;
      const bool drawn = renderer.draw(target, params, capture);
      if (drawn && class_picture) {
        try {
          engine::write_png(*class_picture, cropped(*capture, class_rect));
        } catch (const std::exception& e) {
          class_view.state.export_message = e.what();
        }
        class_picture.reset();
      }
      return drawn;
    });
  }
  renderer.wait_idle();
  options.messages.say(formatted("presented %ld frames", frames.drawn()));
  return 0;
}

}  // namespace needle::app
