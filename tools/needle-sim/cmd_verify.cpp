// needle-sim verify: each complete session's recording replayed through its recorded task, the
// stored score, steps and metrics compared with the replay's (app/verify_report.hpp).
#include <thread>

#include "app/default_db.hpp"
#include "app/verify_report.hpp"
#include "command.hpp"
#include "flag_ranges.hpp"
#include "printed_messages.hpp"

namespace needle::cli {
namespace {

struct VerifyFlags {
  std::optional<std::string> db;
  std::optional<long long> session;
  bool all = false;
  std::string out = "out/verify";
  long long jobs = std::max(1u, std::thread::hardware_concurrency());
};

int run(const VerifyFlags& f) {
  if (f.all == f.session.has_value()) throw UsageError("give --session ID or --all");
  app::VerifyOptions options;
  options.db = app::db_location(f.db);
  if (f.session) options.session = *f.session;
  options.out = f.out;
  options.jobs = int(f.jobs);
  options.messages = printed_messages("needle-sim verify");
  return app::write_verify_report(options);
}

// The options of verify, declared; what runs it once they are parsed.
Runner declare(CLI::App& app) {
  auto f = std::make_shared<VerifyFlags>();
  add_text(app, "--db", f->db, "FILE|URI",
           "session database, an SQLite file or postgresql://... (default: $NEEDLE_DB, else\n"
           "$XDG_DATA_HOME or ~/.local/share, needle-sim/sessions.db)");
  CLI::Option* session = add_whole(app, "--session", f->session, kSessionIds, "ID", "the session to verify");
  add_flag(app, "--all", f->all, "every complete session")->excludes(session);
  add_text(app, "--out", f->out, "DIR", "where verify.json and verify_mismatches.csv go");
  add_whole(app, "--jobs", f->jobs, kVerifyJobs, "N", "replays at once (default: the processor's cores)");
  app.footer(
      "Replays each session's recording through the task it recorded and compares the stored score,\n"
      "steps and metrics with the replay's, bit for bit; prints and exports every difference and keeps\n"
      "each check in the store (the review marks sessions verified, mismatch or unverified). Exit 1 when\n"
      "a session differs or cannot be replayed.");
  return [f] { return run(*f); };
}

const CommandRegistrar reg{
    {"verify", "each complete session's stored score checked against its recording's replay", declare}};

}  // namespace
}  // namespace needle::cli
