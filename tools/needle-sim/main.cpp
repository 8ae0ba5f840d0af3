// needle-sim: one executable, subcommands registered by the cmd_*.cpp files beside this one.
#include <algorithm>
#include <cstdio>
#include <exception>
#include <sstream>

#include "app/default_db.hpp"
#include "app/settings.hpp"
#include "app/start_screen.hpp"
#include "arg_list.hpp"
#include "asset_path.hpp"
#include "command.hpp"
#include "engine/window.hpp"

namespace needle::cli {
namespace {

std::vector<Command>& registry() {
  static std::vector<Command> commands;
  return commands;
}

std::vector<std::string> split_words(const std::string& s) {
  std::istringstream in(s);
  std::vector<std::string> words;
  for (std::string w; in >> w;) words.push_back(w);
  return words;
}

void print_overview() {
  std::printf("needle-sim: needle-procedure training simulator with force feedback\n\n"
              "usage: needle-sim [--db FILE|URI] [--station NAME]\n"
              "                                      the start screen (a window): choose a task and a device, and go;\n"
              "                                      its sessions go to --db (default: $NEEDLE_DB, else\n"
              "                                      ~/.local/share/needle-sim/sessions.db), as run's do\n"
              "       needle-sim COMMAND [options]   (needle-sim COMMAND --help for its options)\n\ncommands:\n");
  for (const auto& c : registered_commands()) {
    std::string first_line = c.usage.substr(0, c.usage.find('\n'));
    std::printf("  %s\n", first_line.c_str());
  }
}

// The registered command whose name words match the longest prefix of argv.
const Command* find_command(const std::vector<std::string>& argv, size_t& words_used) {
  const Command* best = nullptr;
  words_used = 0;
  for (const auto& c : registered_commands()) {
    auto words = split_words(c.name);
    if (words.size() <= argv.size() && std::equal(words.begin(), words.end(), argv.begin()) &&
        words.size() > words_used) {
      best = &c;
      words_used = words.size();
    }
  }
  return best;
}

// The commands whose first word is `word` ("bench": bench deform, bench tick, ...) with more words.
std::vector<const Command*> group_of(const std::string& word) {
  std::vector<const Command*> group;
  for (const auto& c : registered_commands()) {
    const auto words = split_words(c.name);
    if (words.size() > 1 && words[0] == word) group.push_back(&c);
  }
  return group;
}

// `needle-sim bench`, `bench --help`, `bench frobnicate`: what the group has. Exit 0 for help.
int print_group(const std::vector<std::string>& args, const std::vector<const Command*>& group) {
  const bool help = args.size() == 2 && (args[1] == "--help" || args[1] == "-h");
  if (args.size() > 1 && !help && args[1].rfind("-", 0) != 0)
    std::fprintf(stderr, "needle-sim: unknown command '%s %s'\n", args[0].c_str(), args[1].c_str());
  std::FILE* to = help ? stdout : stderr;
  std::fprintf(to, "needle-sim %s: one of\n", args[0].c_str());
  for (const Command* c : group) std::fprintf(to, "  %s\n", c->usage.substr(0, c->usage.find('\n')).c_str());
  std::fprintf(to, "(needle-sim %s NAME --help shows its options)\n", args[0].c_str());
  return help ? 0 : 2;
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
  std::vector<std::string> args(argv + 1, argv + argc);
  // The start screen: no command, only where its sessions go.
  const bool start_screen = args.empty() || args[0].rfind("--db", 0) == 0 || args[0].rfind("--station", 0) == 0;
  if (start_screen && needle::engine::Window::display_available()) {
    try {
      ArgList options(args);
      const std::string db = needle::app::db_location(options.value("--db"));
      const std::string station = needle::app::station_name(options.value("--station"));
      options.finish();
      return needle::app::run_start_screen({asset_dir() / "tasks", db, station, needle::app::default_settings_file()});
    } catch (const UsageError& e) {
      std::fprintf(stderr, "needle-sim: %s (needle-sim --help shows the options)\n", e.what());
      return 2;
    } catch (const std::exception& e) {
      std::fprintf(stderr, "needle-sim: error: %s\n", e.what());
      return 1;
    }
  }
  if (start_screen) {
    std::fprintf(stderr,
                 "needle-sim: no display, so no start screen; needle-sim run runs the guided task headless "
                 "(tools/run-main.sh builds and runs it)\n\n");
    print_overview();
    return 2;
  }
  if (args[0] == "--help" || args[0] == "-h" || args[0] == "help") {
    print_overview();
    return 0;
  }
  size_t used = 0;
  const Command* command = find_command(args, used);
  if (!command) {
    const std::vector<const Command*> group = group_of(args[0]);
    if (!group.empty()) return print_group(args, group);
    std::fprintf(stderr, "needle-sim: unknown command '%s' (needle-sim --help lists them)\n", args[0].c_str());
    return 2;
  }
  ArgList rest(std::vector<std::string>(args.begin() + static_cast<long>(used), args.end()));
  if (rest.wants_help()) {
    std::printf("%s\n", command->usage.c_str());
    return 0;
  }
  try {
    return command->run(rest);
  } catch (const UsageError& e) {
    std::fprintf(stderr, "needle-sim %s: %s (needle-sim %s --help shows the options)\n", command->name.c_str(),
                 e.what(), command->name.c_str());
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "needle-sim %s: error: %s\n", command->name.c_str(), e.what());
    return 1;
  }
}
