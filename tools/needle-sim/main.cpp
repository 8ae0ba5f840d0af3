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
#include "printed_messages.hpp"

namespace needle::cli {
namespace {

std::vector<Command>& registry() {
  static std::vector<Command> commands;
  return commands;
}

// "needle-sim bench tick": the app's words from the root.
std::string full_name(const CLI::App* app) {
  std::string name = app->get_name();
  for (const CLI::App* p = app->get_parent(); p; p = p->get_parent()) name = p->get_name() + " " + name;
  return name;
}

// The usage line made from the options: required ones bare, the others in brackets, two that
// exclude each other as alternatives ("[--task FILE | --scene FILE]"), wrapped under the name.
class SynopsisFormatter : public CLI::Formatter {
 public:
  std::string make_usage(const CLI::App* app, std::string) const override {
    const std::string name = full_name(app);
    std::vector<std::string> parts;
    std::vector<const CLI::Option*> shown;
    for (const CLI::Option* opt : app->get_options()) {
      if (opt == app->get_help_ptr() || opt->get_group().empty()) continue;
      if (std::find(shown.begin(), shown.end(), opt) != shown.end()) continue;
      std::string part = word(opt);
      for (const CLI::Option* other : opt->get_excludes()) {
        part += " | " + word(other);
        shown.push_back(other);
      }
      shown.push_back(opt);
      parts.push_back(opt->get_required() ? part : "[" + part + "]");
    }
    if (app->get_subcommands({}).empty()) return "usage: " + wrapped(name, parts) + "\n";
    // A root or a group: its own options (the root's, for the start screen), then its commands.
    return "usage: " + (parts.empty() ? "" : wrapped(name, parts) + "\n       ") + name + " COMMAND [options]\n";
  }

  // "needle-sim bench tick [--scenario FILE] ...", wrapped at 110 columns under the name.
  static std::string wrapped(const std::string& name, const std::vector<std::string>& parts) {
    std::string out = name, line = name;
    const std::string indent(std::string("usage: ").size() + name.size() + 1, ' ');
    for (const std::string& part : parts) {
      if (line.size() + 1 + part.size() > 110 && line.size() > indent.size()) {
        out += "\n" + indent.substr(std::string("usage: ").size());
        line = indent;
      } else {
        out += " ";
        line += " ";
      }
      out += part;
      line += part;
    }
    return out;
  }

  // An option's value as its form alone ("--ticks N"): the usage line shows what is required and
  // what excludes what.
  std::string make_option_opts(const CLI::Option* opt) const override {
    return opt->get_type_size() != 0 && !opt->get_type_name().empty() ? " " + opt->get_type_name() : "";
  }

  // The commands below the app, each by its full name with its summary: every command for the
  // root (needle-sim --help), a group's own for a group (needle-sim bench --help).
  std::string make_subcommands(const CLI::App* app, CLI::AppFormatMode) const override {
    std::string out;
    std::function<void(const CLI::App*)> list = [&](const CLI::App* parent) {
      for (const CLI::App* sub : parent->get_subcommands({})) {
        if (!sub->get_subcommands({}).empty()) {
          list(sub);
          continue;
        }
        const std::string name = full_name(sub);
        out += "  " + name + std::string(std::max<size_t>(2, 32 - name.size()), ' ') + sub->get_description() + "\n";
      }
    };
    list(app);
    return out.empty() ? out : "\ncommands (COMMAND --help shows its options):\n" + out;
  }

 private:
  static std::string word(const CLI::Option* opt) {
    return opt->get_name() +
           (opt->get_type_size() != 0 && !opt->get_type_name().empty() ? " " + opt->get_type_name() : "");
  }
};

// The deepest command parsed so far: the root when none.
CLI::App* chosen(CLI::App& root) {
  CLI::App* app = &root;
  while (!app->get_subcommands().empty()) app = app->get_subcommands().front();
  return app;
}

bool is_group(const CLI::App* app) { return app->get_parent() && !app->get_subcommands({}).empty(); }

struct StartScreenOptions {
  std::optional<std::string> db, station;
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
                                app::default_settings_file(), printed_messages("needle-sim")});
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
  const auto formatter = std::make_shared<SynopsisFormatter>();
  formatter->column_width(22);
  root.formatter(formatter);
  StartScreenOptions start;
  add_text(root, "--db", start.db, "FILE|URI", "the start screen's session store: an SQLite file or postgresql://...");
  add_text(root, "--station", start.station, "NAME", "the station its sessions ran on (default: the host name)");

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
  if (app != &root && (start.db || start.station)) {
    std::fprintf(stderr,
                 "needle-sim: --db and --station before a command are the start screen's; give them after '%s'\n",
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
