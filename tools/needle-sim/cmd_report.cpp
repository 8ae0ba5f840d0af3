// needle-sim report: one session's review exported headless (app/session_report.hpp).
#include <cmath>

#include "arg_list.hpp"
#include "command.hpp"
#include "app/default_db.hpp"
#include "app/session_report.hpp"

namespace needle::cli {
namespace {

namespace fs = std::filesystem;

int64_t parse_session_id(const std::string& text) {
  const double id = parse_number(text, "--session");
  if (id < 1 || id != std::floor(id) || id > 9e15) throw UsageError("--session: expected a session id (a whole number >= 1), got '" + text + "'");
  return int64_t(id);
}

int run_report(ArgList& args) {
  const int64_t id = parse_session_id(args.required("--session"));
  const fs::path db = args.value("--db").value_or(app::default_db().string());
  const fs::path out = args.required("--out");
  std::optional<double> at;
  if (auto text = args.value("--at")) at = parse_number(*text, "--at");
  args.finish();

  return app::write_session_report(db, id, out, at);
}

const CommandRegistrar reg{
    {"report",
     "needle-sim report --session ID --out DIR [--db FILE] [--at SECONDS]\n"
     "  --session ID   the session to export (needle-sim review lists them)\n"
     "  --out DIR      where session_ID.json, session_ID.csv, the plots and the panels (PNG) go\n"
     "  --db FILE      session database (default: $XDG_DATA_HOME or ~/.local/share, needle-sim/sessions.db)\n"
     "  --at SECONDS   the moment the replay picture shows (default: the end of the recording)",
     run_report}};

}  // namespace
}  // namespace needle::cli
