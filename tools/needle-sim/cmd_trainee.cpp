// needle-sim trainee rename | renames: an instructor's correction of a trainee's name, logged by
// the store (training::SessionStore::rename_trainee), and the log.
#include <cstdio>

#include "app/default_db.hpp"
#include "command.hpp"

namespace needle::cli {
namespace {

constexpr const char* kDbHelp =
    "session database, an SQLite file or postgresql://... (default: $NEEDLE_DB, else\n"
    "$XDG_DATA_HOME or ~/.local/share, needle-sim/sessions.db)";

struct RenameFlags {
  std::optional<std::string> db;
  std::string from, to;
};

int rename(const RenameFlags& f) {
  const std::string location = app::db_location(f.db);
  app::require_existing_db(location);
  training::SessionStore store(location);
  const training::TraineeRename r = store.rename_trainee(f.from, f.to);
  std::printf("renamed trainee \"%s\" to \"%s\" in %s (logged at %s%s%s)\n", r.old_name.c_str(), r.new_name.c_str(),
              store.name().c_str(), r.renamed_at.c_str(), r.renamed_by.empty() ? "" : " by ", r.renamed_by.c_str());
  return 0;
}

Runner declare_rename(CLI::App& app) {
  auto f = std::make_shared<RenameFlags>();
  add_text(app, "--from", f->from, "NAME", "the trainee's name as stored")->required();
  add_text(app, "--to", f->to, "NAME", "the corrected name (1 to 64 bytes, no other trainee's)")->required();
  add_text(app, "--db", f->db, "FILE|URI", kDbHelp);
  app.footer(
      "The trainee's sessions keep their trainee under the new name. The store logs every rename (the old\n"
      "and new names, when, and on PostgreSQL the login role: an instructor's, as stations may not\n"
      "rename); needle-sim trainee renames lists them.");
  return [f] { return rename(*f); };
}

struct RenamesFlags {
  std::optional<std::string> db;
};

int renames(const RenamesFlags& f) {
  const std::unique_ptr<training::SessionStore> store = app::open_existing_db(app::db_location(f.db));
  const std::vector<training::TraineeRename> log = store->trainee_renames();
  for (const training::TraineeRename& r : log)
    std::printf("%s  \"%s\" -> \"%s\"%s%s\n", r.renamed_at.c_str(), r.old_name.c_str(), r.new_name.c_str(),
                r.renamed_by.empty() ? "" : "  by ", r.renamed_by.c_str());
  std::printf("%zu rename%s in %s\n", log.size(), log.size() == 1 ? "" : "s", store->name().c_str());
  return 0;
}

Runner declare_renames(CLI::App& app) {
  auto f = std::make_shared<RenamesFlags>();
  add_text(app, "--db", f->db, "FILE|URI", kDbHelp);
  app.footer("The store's log of trainees renamed, oldest first: when, the old and new names, by whom.");
  return [f] { return renames(*f); };
}

const CommandRegistrar rename_command{
    {"trainee rename", "an instructor's correction of a trainee's name, logged by the store", declare_rename}};
const CommandRegistrar renames_command{{"trainee renames", "the store's log of trainees renamed", declare_renames}};

}  // namespace
}  // namespace needle::cli
