// needle-sim review: the instructor's review window (app/review_window.hpp).
#include <cstdio>

#include "arg_list.hpp"
#include "command.hpp"
#include "app/default_db.hpp"
#include "app/review_window.hpp"

namespace needle::cli {
namespace {

int run_review(ArgList& args) {
  app::ReviewOptions options;
  options.db = app::db_location(args.value("--db"));
  options.size = parse_size(args.value("--size").value_or("1600x900"), "--size");
  if (auto id = args.value("--session")) options.session = parse_whole(*id, "--session", 1, 9000000000000000);
  if (auto frames = args.value("--frames")) options.frames = long(parse_whole(*frames, "--frames", 1, 1000000000));
  options.screenshot = args.value("--screenshot");
  args.finish();
  if (options.screenshot && options.frames == 0) throw UsageError("--screenshot needs --frames N (the frame to capture)");
  return app::run_review_window(options);
}

const CommandRegistrar reg{
    {"review",
     "needle-sim review [--db FILE|URI] [--session ID] [--size WxH] [--frames N] [--screenshot FILE]\n"
     "  --db FILE|URI      session database, an SQLite file or postgresql://... (default: $NEEDLE_DB, else\n"
     "                    $XDG_DATA_HOME or ~/.local/share, needle-sim/sessions.db)\n"
     "  --session ID       the session to open first\n"
     "  --size WxH         window size (default 1600x900)\n"
     "  --frames N         close after N frames\n"
     "  --screenshot FILE  save frame N as presented (needs --frames)\n"
     "  Needs a display; without one, needle-sim report exports a session's review headless.",
     run_review}};

}  // namespace
}  // namespace needle::cli
