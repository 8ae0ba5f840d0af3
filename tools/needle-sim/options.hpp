// The options of needle-sim's commands, declared on their CLI11 apps: one call declares a flag's
// name, the form of its value, its range and default (shown in --help) and checks its text as it
// is parsed. A value that does not fit is a usage error (exit 2) naming the flag, what was
// expected and what was given: "--ticks: expected a whole number from 1 to 100000000, got '0'".
#pragma once

#include <CLI/App.hpp>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "engine/extent.hpp"

namespace needle::cli {

// Wrong or missing arguments found after parsing (two options that do not go together): main
// prints "needle-sim COMMAND: what (needle-sim COMMAND --help shows the options)", exit 2.
struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Whole numbers from lo to hi, both included.
struct WholeRange {
  long long lo = 0, hi = 0;
};
// Numbers from lo to hi; lo itself only when !lo_open.
struct NumberRange {
  double lo = 0.0, hi = 0.0;
  bool lo_open = false;
};

// "1 to 100000000"; "(0, 3600]" or "10 to 36000".
std::string range_text(WholeRange range);
std::string range_text(NumberRange range);

// The texts of values, checked: UsageError "FLAG: expected ..., got 'TEXT'" otherwise. A whole
// number may be written as a decimal ("1e6"); it is checked before any conversion, so
// 9223372036854775807 is refused, not wrapped.
long long parse_whole(const std::string& text, const std::string& flag, WholeRange range);
double parse_number(const std::string& text, const std::string& flag, NumberRange range);
// Comma-separated items, at most max_items: "0.1,0.2,-1".
std::vector<std::string> split_list(const std::string& text, const std::string& flag, size_t max_items);
// "WxH", each side 1 to 16384.
engine::Extent parse_size(const std::string& text, const std::string& flag);

// A list flag holds at most this many items (sizes, spheres, rates, variants, ...): with each
// item's range it bounds the whole run.
inline constexpr size_t kMaxListItems = 16;

// The declarations. `help` is the option's description; the range and the default (the value
// bound when declared, unless `default_text` says otherwise) are added to it.
CLI::Option* add_whole(CLI::App& app, const std::string& flag, long long& value, WholeRange range,
                       const std::string& form, const std::string& help);
CLI::Option* add_whole(CLI::App& app, const std::string& flag, std::optional<long long>& value, WholeRange range,
                       const std::string& form, const std::string& help);
CLI::Option* add_number(CLI::App& app, const std::string& flag, double& value, NumberRange range,
                        const std::string& form, const std::string& help);
CLI::Option* add_number(CLI::App& app, const std::string& flag, std::optional<double>& value, NumberRange range,
                        const std::string& form, const std::string& help);
// Text that may not be empty (a name, a file, a location). `form`: NAME, FILE, DIR, URI, ...
// An empty `value` when declared: no default shown.
CLI::Option* add_text(CLI::App& app, const std::string& flag, std::string& value, const std::string& form,
                      const std::string& help);
CLI::Option* add_text(CLI::App& app, const std::string& flag, std::optional<std::string>& value,
                      const std::string& form, const std::string& help);
// One of `choices`: "FLAG: expected a, b or c, got 'TEXT'". An empty `value`: not given.
CLI::Option* add_choice(CLI::App& app, const std::string& flag, std::string& value,
                        const std::vector<std::string>& choices, const std::string& help);
// "--passivity on|off|both": the tool law's passivity controller in a bench's closed-loop runs, on (the
// scenario's setting), off, or both in turn, alternated run by run (docs/CONTROLLER.md, "Passivity
// guaranteed"); passivity_settings gives the runs' settings, {true}, {false} or {true, false}.
CLI::Option* add_passivity(CLI::App& app, std::string& value);
std::vector<bool> passivity_settings(const std::string& value);
// A file written when the work is done: its folder must exist now, not be found missing after
// ("FLAG: folder F does not exist").
CLI::Option* add_output_file(CLI::App& app, const std::string& flag, std::optional<std::string>& value,
                             const std::string& form, const std::string& help);
CLI::Option* add_size(CLI::App& app, const std::string& flag, engine::Extent& value, const std::string& help);
// MSAA samples: 1, 2, 4 or 8 (the renderer caps them at what the device has).
CLI::Option* add_msaa(CLI::App& app, const std::string& flag, std::optional<int>& value, const std::string& help);
// A list of MSAA sample counts, each 1, 2, 4 or 8.
CLI::Option* add_msaa_list(CLI::App& app, const std::string& flag, std::vector<int>& value, const std::string& help);
// "auto" (nullopt) or a fixed render scale in the engine's range (engine::kRenderScaleRange).
CLI::Option* add_render_scale(CLI::App& app, const std::string& flag, std::optional<float>& value,
                              const std::string& help);
// Comma-separated numbers, each in `each`, at most kMaxListItems (or `max_items`).
CLI::Option* add_number_list(CLI::App& app, const std::string& flag, std::vector<double>& value, NumberRange each,
                             const std::string& form, const std::string& help, size_t max_items = kMaxListItems);
CLI::Option* add_whole_list(CLI::App& app, const std::string& flag, std::vector<long long>& value, WholeRange each,
                            const std::string& form, const std::string& help);
// --db FILE|URI: the session database of run, review and report (app::db_location gives the default).
CLI::Option* add_db(CLI::App& app, std::optional<std::string>& value);
// A flag without a value.
CLI::Option* add_flag(CLI::App& app, const std::string& flag, bool& value, const std::string& help);

}  // namespace needle::cli
