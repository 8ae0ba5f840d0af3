// needle-sim trainee rename | renames: an instructor's correction of a trainee's name, logged by
// the store (training::SessionStore::rename_trainee), and the log.
#include <cstdio>

#include "arg_list.hpp"
#include "command.hpp"
#include "app/default_db.hpp"

namespace needle::cli {
namespace {

int run_rename(ArgList& args) {
  const std::string db = app::db_location(args.value("--db"));
  const std::string from = args.required("--from"), to = args.required("--to");
  args.finish();
  training::SessionStore store(db);
  const training::TraineeRename r = store.rename_trainee(from, to);
  std::printf("renamed trainee \"%s\" to \"%s\" in %s (logged at %s%s%s)\n", r.old_name.c_str(), r.new_name.c_str(),
              store.name().c_str(), r.renamed_at.c_str(), r.renamed_by.empty() ? "" : " by ", r.renamed_by.c_str());
  return 0;
}

int run_renames(ArgList& args) {
  const std::string db = app::db_location(args.value("--db"));
  args.finish();
  const std::unique_ptr<training::SessionStore> store = app::open_existing_db(db);
  const std::vector<training::TraineeRename> log = store->trainee_renames();
  for (const training::TraineeRename& r : log)
    std::printf("%s  \"%s\" -> \"%s\"%s%s\n", r.renamed_at.c_str(), r.old_name.c_str(), r.new_name.c_str(),
                r.renamed_by.empty() ? "" : "  by ", r.renamed_by.c_str());
  std::printf("%zu rename%s in %s\n", log.size(), log.size() == 1 ? "" : "s", store->name().c_str());
  return 0;
}

const CommandRegistrar rename_command{
    {"trainee rename",
     "needle-sim trainee rename --from NAME --to NAME [--db FILE|URI]\n"
     "  --from NAME    the trainee's name as stored\n"
     "  --to NAME      the corrected name (1 to 64 bytes, no other trainee's)\n"
     "  --db FILE|URI  session database (default: $NEEDLE_DB, else $XDG_DATA_HOME or ~/.local/share,\n"
     "                 needle-sim/sessions.db)\n"
     "  The trainee's sessions keep their trainee under the new name. The store logs every rename (the old\n"
     "  and new names, when, and on PostgreSQL the login role: an instructor's, as stations may not\n"
     "  rename); needle-sim trainee renames lists them.",
     run_rename}};

const CommandRegistrar renames_command{
    {"trainee renames",
     "needle-sim trainee renames [--db FILE|URI]\n"
     "  --db FILE|URI  session database (default: $NEEDLE_DB, else $XDG_DATA_HOME or ~/.local/share,\n"
     "                 needle-sim/sessions.db)\n"
     "  The store's log of trainees renamed, oldest first: when, the old and new names, by whom.",
     run_renames}};

}  // namespace
}  // namespace needle::cli
