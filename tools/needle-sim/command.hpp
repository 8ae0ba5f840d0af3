// Subcommand registry of the needle-sim executable. Each cmd_*.cpp registers itself with a
// static CommandRegistrar, so adding a subcommand touches no shared file.
#pragma once

#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace needle::cli {

class ArgList;

// Wrong or missing command-line arguments: main prints the message and the command's usage,
// and exits with code 2.
struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

struct Command {
  std::string name;   // one or more words, e.g. "render" or "bench render"
  std::string usage;  // full --help text: synopsis line, then one line per option
  int (*run)(ArgList& args);
};

struct CommandRegistrar {
  explicit CommandRegistrar(Command command);
};

const std::vector<Command>& registered_commands();

}  // namespace needle::cli
