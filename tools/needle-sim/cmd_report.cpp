// needle-sim report: one session's review exported headless (app/session_report.hpp), or with
// --cohort the instructor's class view (app/cohort_report.hpp).
#include <cmath>
#include <limits>
#include <stdexcept>

#include "arg_list.hpp"
#include "command.hpp"
#include "app/cohort_report.hpp"
#include "app/default_db.hpp"
#include "app/session_report.hpp"

namespace needle::cli {
namespace {

namespace fs = std::filesystem;

int run_report(ArgList& args) {
  const bool cohort = args.flag("--cohort");
  const std::string db = app::db_location(args.value("--db"));
  const fs::path out = args.required("--out");
  if (cohort) {
    training::CohortFilter filter;
    filter.task = args.value("--task").value_or("");
    filter.trainee = args.value("--trainee").value_or("");
    filter.station = args.value("--station").value_or("");
    filter.since = args.value("--since").value_or("");
    filter.until = args.value("--until").value_or("");
    args.finish();
    try {
      training::check_cohort_filter(filter);
    } catch (const std::invalid_argument& e) {
      throw UsageError(e.what());
    }
    return app::write_cohort_report(db, filter, out);
  }
  const int64_t id = parse_whole(args.required("--session"), "--session", 1, 9000000000000000);
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
     "needle-sim report --session ID --out DIR [--db FILE|URI] [--at SECONDS] [--from SECONDS] [--to SECONDS]\n"
     "       needle-sim report --cohort --out DIR [--db FILE|URI] [--task NAME] [--trainee NAME] [--station NAME]\n"
     "                         [--since YYYY-MM-DD] [--until YYYY-MM-DD]\n"
     "  --session ID   the session to export (needle-sim review lists them)\n"
     "  --out DIR      where session_ID.json, session_ID.csv, the plots and the panels (PNG) go; with --cohort,\n"
     "                 cohort.json, cohort_curves.csv, cohort_failed_steps.csv, cohort_percentiles.csv and the\n"
     "                 learning curves, cohort_TASK_score.png and cohort_TASK_time_to_target.png\n"
     "  --db FILE|URI  session database, an SQLite file or postgresql://... (default: $NEEDLE_DB, else\n"
     "                 $XDG_DATA_HOME or ~/.local/share, needle-sim/sessions.db)\n"
     "  --at SECONDS   the moment the replay picture shows (default: the end of the recording)\n"
     "  --from, --to   the time range the plots show (default: the whole recording)\n"
     "  --cohort       the class view of every complete session: per trainee and task the score over attempts,\n"
     "                 first-pass success, time to target; the steps most failed; percentiles of every metric\n"
     "  --task, --trainee, --station NAME, --since, --until DATE (UTC, inclusive): only those sessions",
     run_report}};

}  // namespace
}  // namespace needle::cli
