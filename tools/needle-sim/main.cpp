// needle-sim: one executable, its commands registered by the cmd_*.cpp files beside this one and
// parsed by CLI11. With no command, the start screen. Exit codes: 0 ok, 2 usage, 1 any other
// failure, each failure one line.
#include <CLI/CLI.hpp>
#include <cstdio>
#include <exception>
#include <map>
#include <memory>
#include <sstream>

#include "app/default_db.hpp"
#include "app/settings.hpp"
#include "app/start_screen.hpp"
#include "asset_path.hpp"
#include "command.hpp"
#include "engine/window.hpp"
#include "help_format.hpp"
#include "printed_messages.hpp"

namespace needle::cli {
namespace {

std::vector<Command>& registry() {
  static std::vector<Command> commands;
  return commands;
}

// The deepest command parsed so far: the root when none.
CLI::App* chosen(CLI::App& root) {
  CLI::App* app = &root;
  while (!app->get_subcommands().empty()) app = app->get_subcommands().front();
  return app;
}

bool is_group(const CLI::App* app) { return app->get_parent() && !app->get_subcommands({}).empty(); }

struct StartScreenOptions {
  std::optional<std::string> db, station;
  bool debug = false;
};

int start_screen(const StartScreenOptions& options, const CLI::App& root) {
  if (!engine::Window::display_available()) {
    std::fprintf(stderr,
                 "needle-sim: no display, so no start screen; needle-sim run runs the guided task headless "
                 "(tools/run-main.sh builds and runs it)\n\n%s",
                 root.help().c_str());
    return 2;
  }
  return app::run_start_screen({asset_dir() / "tasks", app::db_location(options.db), app::station_name(options.station),
                                app::default_settings_file(), printed_messages("needle-sim"), options.debug});
}

int run_command(const CLI::App* command, const Runner& runner) {
  const std::string name = full_name(command);
  try {
    return runner();
  } catch (const UsageError& e) {
    std::fprintf(stderr, "%s: %s (%s --help shows the options)\n", name.c_str(), e.what(), name.c_str());
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s: error: %s\n", name.c_str(), e.what());
    return 1;
  }
}

}  // namespace

CommandRegistrar::CommandRegistrar(Command command) { registry().push_back(std::move(command)); }

const std::vector<Command>& registered_commands() {
  auto& r = registry();
  std::sort(r.begin(), r.end(), [](const Command& a, const Command& b) { return a.name < b.name; });
  return r;
}

}  // namespace needle::cli

int main(int argc, char** argv) {
  using namespace needle::cli;
  CLI::App root("needle-sim: needle-procedure training simulator with force feedback", "needle-sim");
  root.formatter(help_formatter());
  StartScreenOptions start;
  add_text(root, "--db", start.db, "FILE|URI", "the start screen's session store: an SQLite file or postgresql://...");
  add_text(root, "--station", start.station, "NAME", "the station its sessions ran on (default: the host name)");
  add_flag(root, "--debug", start.debug, "the start screen and its tasks with the status panel (F3 toggles it)");

  // The command tree: "bench render" under a group app "bench".
  std::map<const CLI::App*, Runner> runners;
  for (const Command& command : registered_commands()) {
    CLI::App* parent = &root;
    std::istringstream words(command.name);
    std::vector<std::string> path;
    for (std::string w; words >> w;) path.push_back(w);
    for (size_t i = 0; i + 1 < path.size(); ++i) {
      CLI::App* group = nullptr;
      for (CLI::App* sub : parent->get_subcommands({}))
        if (sub->get_name() == path[i]) group = sub;
      if (!group) group = parent->add_subcommand(path[i], "benchmarks: each prints a table and takes --json FILE");
      parent = group;
    }
    CLI::App* app = parent->add_subcommand(path.back(), command.summary);
    runners[app] = command.declare(*app);
  }

  root.footer(
      "With no command, the start screen (a window): choose a task and a device, and go; its sessions go to\n"
      "--db (default: $NEEDLE_DB, else ~/.local/share/needle-sim/sessions.db), as run's do.");

  std::vector<std::string> args(argv + 1, argv + argc);
  if (args.size() == 1 && args[0] == "help") {
    std::printf("%s", root.help().c_str());
    return 0;
  }
  try {
    root.parse(argc, argv);
  } catch (const CLI::CallForHelp&) {
    const CLI::App* app = chosen(root);
    std::printf("%s", app->help().c_str());
    return 0;
  } catch (const CLI::ParseError& e) {
    const CLI::App* app = chosen(root);
    const std::string name = full_name(app);
    // A word where a command was expected: `needle-sim frobnicate`, `needle-sim bench frobnicate`.
    const std::vector<std::string> extra = app->remaining();
    if (dynamic_cast<const CLI::ExtrasError*>(&e) && !extra.empty() && extra.front().rfind("-", 0) != 0 &&
        (app == &root || is_group(app))) {
      const std::string words = (app == &root ? "" : name.substr(root.get_name().size() + 1) + " ") + extra.front();
      std::fprintf(stderr, "needle-sim: unknown command '%s'%s", words.c_str(),
                   app == &root ? " (needle-sim --help lists them)\n" : ("\n" + app->help()).c_str());
      return 2;
    }
    std::fprintf(stderr, "%s: %s (%s --help shows the options)\n", name.c_str(), e.what(), name.c_str());
    return 2;
  }
  const CLI::App* app = chosen(root);
  if (app != &root && (start.db || start.station || start.debug)) {
    std::fprintf(
        stderr,
        "needle-sim: --db, --station and --debug before a command are the start screen's; give them after '%s'\n",
        full_name(app).substr(root.get_name().size() + 1).c_str());
    return 2;
  }
  if (app == &root) {
    try {
      return start_screen(start, root);
    } catch (const std::exception& e) {
      std::fprintf(stderr, "needle-sim: error: %s\n", e.what());
      return 1;
    }
  }
  if (is_group(app)) {
    std::fprintf(stderr, "%s", app->help().c_str());
    return 2;
  }
  return run_command(app, runners.at(app));
}
