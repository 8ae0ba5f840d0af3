// needle-sim report: one session's review exported headless (app/session_report.hpp).
#include <cmath>
#include <limits>

#include "arg_list.hpp"
#include "command.hpp"
#include "app/default_db.hpp"
#include "app/session_report.hpp"

namespace needle::cli {
namespace {

namespace fs = std::filesystem;

int run_report(ArgList& args) {
  const int64_t id = parse_whole(args.required("--session"), "--session", 1, 9000000000000000);
  const fs::path db = args.value("--db").value_or(app::default_db().string());
  const fs::path out = args.required("--out");
  std::optional<double> at;
  if (auto text = args.value("--at")) at = parse_number(*text, "--at");
  const std::optional<std::string> from = args.value("--from"), to = args.value("--to");
  args.finish();
  ui::TimeSpan plots;  // unchosen: the whole recording
  if (from || to) {
    plots.lo = from ? parse_number(*from, "--from") : -std::numeric_limits<double>::infinity();
    plots.hi = to ? parse_number(*to, "--to") : std::numeric_limits<double>::infinity();
    if (!(plots.hi > plots.lo)) throw UsageError("--to must be later than --from");
  }

  return app::write_session_report(db, id, out, at, plots);
}

const CommandRegistrar reg{
    {"report",
     "needle-sim report --session ID --out DIR [--db FILE] [--at SECONDS] [--from SECONDS] [--to SECONDS]\n"
     "  --session ID   the session to export (needle-sim review lists them)\n"
     "  --out DIR      where session_ID.json, session_ID.csv, the plots and the panels (PNG) go\n"
     "  --db FILE      session database (default: $XDG_DATA_HOME or ~/.local/share, needle-sim/sessions.db)\n"
     "  --at SECONDS   the moment the replay picture shows (default: the end of the recording)\n"
     "  --from, --to   the time range the plots show (default: the whole recording)",
     run_report}};

}  // namespace
}  // namespace needle::cli
