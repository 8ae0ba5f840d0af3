// needle-sim review: the instructor's review window (app/review_window.hpp).
#include "app/default_db.hpp"
#include "app/review_window.hpp"
#include "command.hpp"
#include "flag_ranges.hpp"
#include "printed_messages.hpp"

namespace needle::cli {
namespace {

struct ReviewFlags {
  std::optional<std::string> db;
  std::optional<long long> session, frames;
  app::ReviewOptions window;
};

int run(const ReviewFlags& f) {
  app::ReviewOptions options = f.window;
  options.db = app::db_location(f.db);
  if (f.session) options.session = *f.session;
  if (f.frames) options.frames = long(*f.frames);
  options.messages = printed_messages("needle-sim review");
  if (options.screenshot && options.frames == 0)
    throw UsageError("--screenshot needs --frames N (the frame to capture)");
  return app::run_review_window(options);
}

// The options of review, declared; what runs it once they are parsed.
Runner declare(CLI::App& app) {
  auto f = std::make_shared<ReviewFlags>();
  add_db(app, f->db);
  add_whole(app, "--session", f->session, kSessionIds, "ID", "the session to open first");
  add_flag(app, "--class", f->window.class_view,
           "open on the Class tab: the class view of report --cohort, with its filters and export");
  add_size(app, "--size", f->window.size, "window size");
  add_whole(app, "--frames", f->frames, kWindowFrames, "N", "close after N frames");
  add_text(app, "--screenshot", f->window.screenshot, "FILE", "save frame N as presented (needs --frames)");
  app.footer("Needs a display; without one, needle-sim report exports a session's review headless.");
  return [f] { return run(*f); };
}

const CommandRegistrar reg{
    {"review", "the instructor's review window: sessions, metrics, plots, replay; the class view", declare}};

}  // namespace
}  // namespace needle::cli
