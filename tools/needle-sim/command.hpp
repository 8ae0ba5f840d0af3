// The commands of needle-sim. Each cmd_*.cpp registers one with a static CommandRegistrar: its
// name, a one-line summary and a function that declares its options on its CLI11 app (CLI11
// makes the usage, the checks and --help from them) and returns what runs it once they are
// parsed. Adding a command touches no shared file.
#pragma once

#include <CLI/App.hpp>
#include <functional>
#include <string>
#include <vector>

#include "options.hpp"

namespace needle::cli {

// Runs a command whose options are parsed: its exit code. Throws UsageError (exit 2) or any
// other exception (exit 1, its one line printed).
using Runner = std::function<int()>;

struct Command {
  std::string name;     // one or more words: "render", "bench render"
  std::string summary;  // one line, for needle-sim --help and the group's list
  std::function<Runner(CLI::App& app)> declare;
};

struct CommandRegistrar {
  explicit CommandRegistrar(Command command);
};

// Every registered command, sorted by name.
const std::vector<Command>& registered_commands();

}  // namespace needle::cli
