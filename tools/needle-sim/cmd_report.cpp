// needle-sim report: one session's review exported headless (app/session_report.hpp).
#include <cmath>

#include "arg_list.hpp"
#include "command.hpp"
#include "app/default_db.hpp"
#include "app/session_report.hpp"

namespace needle::cli {
namespace {

namespace fs = std::filesystem;

int run_report(ArgList& args) {
  const int64_t id = parse_whole(args.required("--session"), "--session", 1, 9000000000000000);
  const std::string db = app::db_location(args.value("--db"));
  const fs::path out = args.required("--out");
  std::optional<double> at;
  if (auto text = args.value("--at")) at = parse_number(*text, "--at");
  args.finish();

  return app::write_session_report(db, id, out, at);
}

const CommandRegistrar reg{
    {"report",
     "needle-sim report --session ID --out DIR [--db FILE|URI] [--at SECONDS]\n"
     "  --session ID   the session to export (needle-sim review lists them)\n"
     "  --out DIR      where session_ID.json, session_ID.csv, the plots and the panels (PNG) go\n"
     "  --db FILE|URI  session database, an SQLite file or postgresql://... (default: $NEEDLE_DB, else\n"
     "                 $XDG_DATA_HOME or ~/.local/share, needle-sim/sessions.db)\n"
     "  --at SECONDS   the moment the replay picture shows (default: the end of the recording)",
     run_report}};

}  // namespace
}  // namespace needle::cli
