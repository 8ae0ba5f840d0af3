// The arguments after a subcommand's name, consumed flag by flag; whatever is left at
// finish() is a usage error, so a mistyped flag is never silently ignored.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "engine/extent.hpp"

namespace needle::cli {

class ArgList {
 public:
  explicit ArgList(std::vector<std::string> args);

  // "--flag VALUE" or "--flag=VALUE"; nullopt when absent. Throws UsageError when the value
  // is missing or the flag is given twice.
  std::optional<std::string> value(const std::string& flag);
  std::string required(const std::string& flag);
  // A flag without a value ("--headless").
  bool flag(const std::string& flag);
  // Throws UsageError naming every argument nobody asked for.
  void finish() const;

  bool wants_help() const;

 private:
  std::vector<std::string> args_;
  std::vector<bool> used_;
};

// Parses "WxH" (e.g. "1280x720") into positive width and height; UsageError otherwise.
engine::Extent parse_size(const std::string& text, const std::string& flag);

// Parses a decimal number with nothing after it; UsageError naming the flag otherwise.
double parse_number(const std::string& text, const std::string& flag);
// A whole number in [lo, hi]; UsageError "FLAG: expected a whole number from LO to HI, got 'TEXT'"
// otherwise (checked before any conversion, so 9223372036854775807 is refused, not wrapped).
long long parse_whole(const std::string& text, const std::string& flag, long long lo, long long hi);
// "--flag FILE" for a file the command writes when its work is done: the file's folder must exist
// now, not be found missing after the work (UsageError naming the flag and the folder).
std::optional<std::string> output_file(ArgList& args, const std::string& flag);
// MSAA sample count: 1, 2, 4 or 8 (the renderer caps it at what the device has).
int parse_msaa(const std::string& text, const std::string& flag);
// "auto" (nullopt) or a render scale in [0.25, 1].
std::optional<float> parse_render_scale(const std::string& text, const std::string& flag);
// "on", "off" or "both": the settings a bench runs in turn ({true}, {false} or {true, false}).
std::vector<bool> parse_on_off_both(const std::string& text, const std::string& flag);
// Comma-separated numbers, "0.1,0.2,-1".
std::vector<double> parse_number_list(const std::string& text, const std::string& flag);

// An output file's folder must exist before a run, not be found missing after it: UsageError
// naming the flag and the folder otherwise. Nothing to check without a file.
void check_output_folder(const std::optional<std::string>& file, const std::string& flag);

}  // namespace needle::cli
