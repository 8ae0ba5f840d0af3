// needle-sim sync: sends the sessions this station kept while the server was lost
// (training/sessions/session_sync.hpp). Sending twice stores each session once.
#include <cstdio>

#include "app/default_db.hpp"
#include "command.hpp"
#include "training/sessions/session_sync.hpp"
#include "training/sessions/store_location.hpp"

namespace needle::cli {
namespace {

struct SyncFlags {
  std::optional<std::string> db, local;
};

int run(const SyncFlags& f) {
  const std::string server = app::db_location(f.db);
  const std::string local_file = f.local.value_or(app::default_db().string());
  if (!training::is_postgres_uri(server))
    throw UsageError("--db " + training::shown_location(server) + ": sync sends to a server, a postgresql:// URI");
  if (!std::filesystem::is_regular_file(local_file))
    throw std::runtime_error(local_file + ": no session database on this station: nothing to send");
  training::SessionStore local(local_file);
  training::SessionStore remote(server);
  const training::SyncReport report = training::sync_outbox(local, local_file, remote);
  for (const std::string& line : report.sent) std::printf("sent %s\n", line.c_str());
  for (const std::string& line : report.failed) std::fprintf(stderr, "needle-sim sync: not sent: %s\n", line.c_str());
  std::printf("%zu sent to %s, %zu not sent, %zu waiting\n", report.sent.size(), remote.name().c_str(),
              report.failed.size(), local.outbox().size());
  return report.failed.empty() ? 0 : 1;
}

// The options of sync, declared; what runs it once they are parsed.
Runner declare(CLI::App& app) {
  auto f = std::make_shared<SyncFlags>();
  add_text(app, "--db", f->db, "URI", "the server: postgresql://USER@HOST/DBNAME[?sslmode=...] (default: $NEEDLE_DB)");
  add_text(app, "--local", f->local, "FILE",
           "this station's own file, where runs kept the sessions the server missed\n"
           "(default: $XDG_DATA_HOME or ~/.local/share, needle-sim/sessions.db)");
  app.footer(
      "Sends each kept session once (by the id its station made), with its recording; exit 1 when one\n"
      "could not be sent (it stays kept for the next sync).");
  return [f] { return run(*f); };
}

const CommandRegistrar reg{
    {"sync", "sends the sessions this station kept while the server could not be reached", declare}};

}  // namespace
}  // namespace needle::cli
