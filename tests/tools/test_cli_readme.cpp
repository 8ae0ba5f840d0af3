// README.md's command table against needle-sim's --help, so the two cannot drift: every command
// `needle-sim --help` lists has a row (the benches one row together), every flag a row names is
// one its command's --help lists, and every flag a command's --help lists is named in its rows
// (a bench's rows name --json, which every bench takes).
#include <gtest/gtest.h>

#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>

#include "cli_process.hpp"
#include "tests/support/test_paths.hpp"

namespace needle::test {
namespace {

using Flags = std::set<std::string>;

Flags flags_in(const std::string& text) {
  Flags flags;
  const std::regex flag("--[a-z][a-z-]*");
  for (auto it = std::sregex_iterator(text.begin(), text.end(), flag); it != std::sregex_iterator(); ++it)
    flags.insert(it->str());
  return flags;
}

// The rows of README.md's command table ("## The command line"): command -> the flags the rows'
// first cells name. A row's command is the leading words of a code span of its first cell
// (`bench render` and the other benches of a row each get the row's flags).
std::map<std::string, Flags> readme_rows() {
  std::ifstream in(source_dir() / "README.md");
  std::map<std::string, Flags> rows;
  bool in_section = false;
  for (std::string line; std::getline(in, line);) {
    if (line.rfind("## ", 0) == 0) in_section = line == "## The command line";
    if (!in_section || line.rfind("| `", 0) != 0) continue;
    const std::string cell = line.substr(2, line.find(" | ") - 2);
    const Flags flags = flags_in(cell);
    std::regex span("`([a-z]+(?: [a-z]+)?)(?=[ `])");
    for (auto it = std::sregex_iterator(cell.begin(), cell.end(), span); it != std::sregex_iterator(); ++it) {
      Flags& row = rows[(*it)[1].str()];
      row.insert(flags.begin(), flags.end());
    }
  }
  return rows;
}

// The commands `needle-sim --help` lists.
std::vector<std::string> help_commands() {
  const ProcessResult help = run_needle_sim("--help");
  std::vector<std::string> commands;
  std::istringstream lines(help.output);
  for (std::string line; std::getline(lines, line);)
    if (line.rfind("  needle-sim ", 0) == 0) commands.push_back(line.substr(13, line.find("  ", 13) - 13));
  return commands;
}

// The flags a command's --help lists under its options (not those its text mentions).
Flags help_flags(const std::string& command) {
  const ProcessResult help = run_needle_sim(command + " --help");
  EXPECT_EQ(help.exit_code, 0) << command;
  Flags flags;
  std::istringstream lines(help.output);
  for (std::string line; std::getline(lines, line);)
    if (line.rfind("  --", 0) == 0) flags.insert(line.substr(2, line.find(' ', 2) - 2));
  return flags;
}

TEST(CliReadme, TheCommandTableAndEachCommandsHelpNameTheSameFlags) {
  const std::map<std::string, Flags> rows = readme_rows();
  ASSERT_FALSE(rows.empty()) << "no command table in README.md";
  for (const std::string& command : help_commands()) {
    const bool bench = command.rfind("bench ", 0) == 0;
    const auto row = rows.find(bench && !rows.count(command) ? "bench" : command);
    ASSERT_NE(row, rows.end()) << "README.md's command table has no row for " << command;
    const Flags help = help_flags(command);
    if (bench) {
      EXPECT_TRUE(help.count("--json")) << command << " takes no --json";
      continue;
    }
    for (const std::string& flag : row->second)
      EXPECT_TRUE(help.count(flag)) << "README.md names " << flag << " for " << command << ", its --help does not";
    for (const std::string& flag : help)
      EXPECT_TRUE(row->second.count(flag)) << command << " --help lists " << flag << ", README.md's row does not";
  }
  for (const auto& [command, flags] : rows) {
    const std::vector<std::string> listed = help_commands();
    EXPECT_TRUE(command == "bench" || std::find(listed.begin(), listed.end(), command) != listed.end())
        << "README.md has a row for " << command << ", needle-sim --help does not list it";
  }
}

}  // namespace
}  // namespace needle::test
