// needle-sim verify: each complete session's recording replayed through its recorded task, the
// stored score, steps and metrics compared with the replay's (app/verify_report.hpp).
#include <thread>

#include "arg_list.hpp"
#include "command.hpp"
#include "app/default_db.hpp"
#include "app/verify_report.hpp"

namespace needle::cli {
namespace {

int run_verify(ArgList& args) {
  app::VerifyOptions options;
  options.db = app::db_location(args.value("--db"));
  const std::optional<std::string> session = args.value("--session");
  const bool all = args.flag("--all");
  options.out = args.value("--out").value_or("out/verify");
  const int cores = int(std::max(1u, std::thread::hardware_concurrency()));
  options.jobs = int(parse_whole(args.value("--jobs").value_or(std::to_string(cores)), "--jobs", 1, 256));
  args.finish();
  if (all == bool(session)) throw UsageError("give --session ID or --all");
  if (session) options.session = parse_whole(*session, "--session", 1, 9000000000000000);
  return app::write_verify_report(options);
}

const CommandRegistrar reg{
    {"verify",
     "needle-sim verify [--db FILE|URI] (--session ID | --all) [--out DIR] [--jobs N]\n"
     "  --db FILE|URI  session database, an SQLite file or postgresql://... (default: $NEEDLE_DB, else\n"
     "                 $XDG_DATA_HOME or ~/.local/share, needle-sim/sessions.db)\n"
     "  --session ID   the session to verify\n"
     "  --all          every complete session\n"
     "  --out DIR      where verify.json and verify_mismatches.csv go (default out/verify)\n"
     "  --jobs N       replays at once, 1 to 256 (default: the processor's cores)\n"
     "  Replays each session's recording through the task it recorded and compares the stored score,\n"
     "  steps and metrics with the replay's, bit for bit; prints and exports every difference and keeps\n"
     "  each check in the store (the review marks sessions verified, mismatch or unverified). Exit 1 when\n"
     "  a session differs or cannot be replayed.",
     run_verify}};

}  // namespace
}  // namespace needle::cli
