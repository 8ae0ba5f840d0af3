// needle-sim report: one session's review exported headless (app/session_report.hpp), or with
// --cohort the instructor's class view (app/cohort_report.hpp).
#include <limits>
#include <stdexcept>

#include "app/cohort_report.hpp"
#include "app/default_db.hpp"
#include "app/session_report.hpp"
#include "command.hpp"
#include "flag_ranges.hpp"
#include "printed_messages.hpp"

namespace needle::cli {
namespace {

struct ReportFlags {
  bool cohort = false;
  std::optional<std::string> db, out;
  std::optional<long long> session;
  std::optional<double> at, from, to;
  training::CohortFilter filter;
};

int run(const ReportFlags& f) {
  const std::string db = app::db_location(f.db);
  if (f.cohort) {
    if (f.session || f.at || f.from || f.to)
      throw UsageError("--cohort reports the class: --session, --at, --from and --to are for one session");
    try {
      training::check_cohort_filter(f.filter);
    } catch (const std::invalid_argument& e) {
      throw UsageError(e.what());
    }
    return app::write_cohort_report(db, f.filter, *f.out, printed_messages("needle-sim report"));
  }
  if (!f.session) throw UsageError("--session is required (or --cohort)");
  const training::CohortFilter none;
  if (!(f.filter == none)) throw UsageError("--task, --trainee, --station, --since and --until filter --cohort");
  ui::TimeSpan plots;  // unchosen: the whole recording
  if (f.from || f.to) {
    plots.lo = f.from.value_or(-std::numeric_limits<double>::infinity());
    plots.hi = f.to.value_or(std::numeric_limits<double>::infinity());
    if (!(plots.hi > plots.lo)) throw UsageError("--to must be later than --from");
  }
  return app::write_session_report(db, *f.session, *f.out, f.at, plots, printed_messages("needle-sim report"));
}

// The options of report, declared; what runs it once they are parsed.
Runner declare(CLI::App& app) {
  auto f = std::make_shared<ReportFlags>();
  CLI::Option* session = add_whole(app, "--session", f->session, kSessionIds, "ID",
                                   "the session to export (needle-sim review lists them)");
  add_flag(app, "--cohort", f->cohort,
           "the class view of every complete session: per trainee and task the score over attempts,\n"
           "first-pass success, time to target; the steps most failed; percentiles of every metric")
      ->excludes(session);
  add_text(app, "--out", f->out, "DIR",
           "where session_ID.json, session_ID.csv, the plots and the panels (PNG) go; with --cohort,\n"
           "cohort.json, cohort_curves.csv, cohort_failed_steps.csv, cohort_percentiles.csv and the\n"
           "learning curves, cohort_TASK_score.png and cohort_TASK_time_to_target.png")
      ->required();
  add_db(app, f->db);
  add_number(app, "--at", f->at, kRecordingTimes_s, "SECONDS",
             "the moment the replay picture shows, by default the end of the recording");
  add_number(app, "--from", f->from, kRecordingTimes_s, "SECONDS",
             "the start of the time range the plots show, by default the recording's");
  add_number(app, "--to", f->to, kRecordingTimes_s, "SECONDS",
             "the end of the time range the plots show, by default the recording's");
  add_text(app, "--task", f->filter.task, "NAME", "--cohort: only this task's sessions");
  add_text(app, "--trainee", f->filter.trainee, "NAME", "--cohort: only this trainee's sessions");
  add_text(app, "--station", f->filter.station, "NAME", "--cohort: only the sessions of this station");
  add_text(app, "--since", f->filter.since, "YYYY-MM-DD",
           "--cohort: only the sessions started on this day (UTC) or later");
  add_text(app, "--until", f->filter.until, "YYYY-MM-DD",
           "--cohort: only the sessions started on this day (UTC) or before");
  return [f] { return run(*f); };
}

const CommandRegistrar reg{
    {"report", "one session's review exported headless, or with --cohort the class view", declare}};

}  // namespace
}  // namespace needle::cli
