#include "options.hpp"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <filesystem>

#include "engine/scene_renderer.hpp"

namespace needle::cli {
namespace {

std::string number_text(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.10g", v);
  return text;
}

// A name, file or location: anything but empty.
const std::string& non_empty(const std::string& text, const std::string& flag, const std::string& form) {
  if (text.empty()) throw UsageError(flag + ": expected " + form + ", got ''");
  return text;
}

// "help (range; default D)", the parts left out that are empty.
std::string described(const std::string& help, const std::string& range, const std::string& default_text) {
  std::string extra = range;
  if (!default_text.empty()) extra += (extra.empty() ? "" : "; ") + std::string("default ") + default_text;
  return extra.empty() ? help : help + " (" + extra + ")";
}

// Runs `parse` on the option's text as it is parsed, a UsageError becoming CLI11's
// ValidationError, which main reports as a usage error.
template <typename Parse>
CLI::Option* option(CLI::App& app, const std::string& flag, Parse parse, const std::string& form,
                    const std::string& help) {
  return app
      .add_option_function<std::string>(
          flag,
          [flag, parse](const std::string& text) {
            try {
              parse(text);
            } catch (const UsageError& e) {
              throw CLI::ValidationError(e.what());
            }
          },
          help)
      ->type_name(form);
}

}  // namespace

std::string range_text(WholeRange range) { return std::to_string(range.lo) + " to " + std::to_string(range.hi); }

std::string range_text(NumberRange range) {
  return range.lo_open ? "(" + number_text(range.lo) + ", " + number_text(range.hi) + "]"
                       : number_text(range.lo) + " to " + number_text(range.hi);
}

double parse_number(const std::string& text, const std::string& flag, NumberRange range) {
  double v = 0.0;
  const char* end = text.data() + text.size();
  const auto [ptr, ec] = std::from_chars(text.data(), end, v);
  const bool in_range = (range.lo_open ? v > range.lo : v >= range.lo) && v <= range.hi;
  if (ec != std::errc() || ptr != end || !std::isfinite(v) || !in_range)
    throw UsageError(flag + ": expected a number " + (range.lo_open ? "in " : "from ") + range_text(range) + ", got '" +
                     text + "'");
  return v;
}

long long parse_whole(const std::string& text, const std::string& flag, WholeRange range) {
  double v = 0.0;
  const char* end = text.data() + text.size();
  const auto [ptr, ec] = std::from_chars(text.data(), end, v);
  if (ec != std::errc() || ptr != end || !(v >= double(range.lo) && v <= double(range.hi)) || v != std::floor(v))
    throw UsageError(flag + ": expected a whole number from " + range_text(range) + ", got '" + text + "'");
  return static_cast<long long>(v);
}

std::vector<std::string> split_list(const std::string& text, const std::string& flag, size_t max_items) {
  std::vector<std::string> items;
  for (size_t start = 0;;) {
    const size_t comma = text.find(',', start);
    items.push_back(text.substr(start, comma - start));
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  if (items.size() > max_items)
    throw UsageError(flag + ": expected at most " + std::to_string(max_items) + " items, got " +
                     std::to_string(items.size()));
  return items;
}

engine::Extent parse_size(const std::string& text, const std::string& flag) {
  const WholeRange side{1, 16384};
  const size_t x = text.find('x');
  auto side_of = [&](const std::string& s) {
    unsigned v = 0;
    const auto [ptr, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
    if (x == std::string::npos || ec != std::errc() || ptr != s.data() + s.size() || v < side.lo || v > side.hi)
      throw UsageError(flag + ": expected WxH with each side from " + range_text(side) + ", got '" + text + "'");
    return v;
  };
  return {side_of(text.substr(0, x)), side_of(x == std::string::npos ? "" : text.substr(x + 1))};
}

CLI::Option* add_whole(CLI::App& app, const std::string& flag, long long& value, WholeRange range,
                       const std::string& form, const std::string& help) {
  return option(
      app, flag, [&value, flag, range](const std::string& t) { value = parse_whole(t, flag, range); }, form,
      described(help, range_text(range), std::to_string(value)));
}

CLI::Option* add_whole(CLI::App& app, const std::string& flag, std::optional<long long>& value, WholeRange range,
                       const std::string& form, const std::string& help) {
  return option(
      app, flag, [&value, flag, range](const std::string& t) { value = parse_whole(t, flag, range); }, form,
      described(help, range_text(range), ""));
}

CLI::Option* add_number(CLI::App& app, const std::string& flag, double& value, NumberRange range,
                        const std::string& form, const std::string& help) {
  return option(
      app, flag, [&value, flag, range](const std::string& t) { value = parse_number(t, flag, range); }, form,
      described(help, range_text(range), number_text(value)));
}

CLI::Option* add_number(CLI::App& app, const std::string& flag, std::optional<double>& value, NumberRange range,
                        const std::string& form, const std::string& help) {
  return option(
      app, flag, [&value, flag, range](const std::string& t) { value = parse_number(t, flag, range); }, form,
      described(help, range_text(range), ""));
}

CLI::Option* add_text(CLI::App& app, const std::string& flag, std::string& value, const std::string& form,
                      const std::string& help) {
  return option(
      app, flag, [&value, flag, form](const std::string& t) { value = non_empty(t, flag, form); }, form,
      described(help, "", value));
}

CLI::Option* add_text(CLI::App& app, const std::string& flag, std::optional<std::string>& value,
                      const std::string& form, const std::string& help) {
  return option(
      app, flag, [&value, flag, form](const std::string& t) { value = non_empty(t, flag, form); }, form, help);
}

CLI::Option* add_choice(CLI::App& app, const std::string& flag, std::string& value,
                        const std::vector<std::string>& choices, const std::string& help) {
  std::string listed, form;
  for (size_t i = 0; i < choices.size(); ++i) {
    listed += (i == 0 ? "" : i + 1 == choices.size() ? " or " : ", ") + choices[i];
    form += (i == 0 ? "" : "|") + choices[i];
  }
  return option(
      app, flag,
      [&value, flag, choices, listed](const std::string& t) {
        for (const std::string& c : choices)
          if (t == c) {
            value = t;
            return;
          }
        throw UsageError(flag + ": expected " + listed + ", got '" + t + "'");
      },
      form, described(help, "", value));
}

CLI::Option* add_passivity(CLI::App& app, std::string& value) {
  return add_choice(app, "--passivity", value, {"on", "off", "both"},
                    "the tool law's passivity controller: on, off, or both in turn for each run (what it costs)");
}

std::vector<bool> passivity_settings(const std::string& value) {
  if (value == "both") return {true, false};
  return {value != "off"};
}

CLI::Option* add_output_file(CLI::App& app, const std::string& flag, std::optional<std::string>& value,
                             const std::string& form, const std::string& help) {
  return option(
      app, flag,
      [&value, flag, form](const std::string& t) {
        const std::filesystem::path folder = std::filesystem::absolute(non_empty(t, flag, form)).parent_path();
        if (!std::filesystem::is_directory(folder))
          throw UsageError(flag + ": folder " + folder.string() + " does not exist");
        value = t;
      },
      form, help);
}

CLI::Option* add_size(CLI::App& app, const std::string& flag, engine::Extent& value, const std::string& help) {
  return option(
      app, flag, [&value, flag](const std::string& t) { value = parse_size(t, flag); }, "WxH",
      described(help, "", std::to_string(value.width) + "x" + std::to_string(value.height)));
}

namespace {
int msaa_of(const std::string& text, const std::string& flag) {
  if (text != "1" && text != "2" && text != "4" && text != "8")
    throw UsageError(flag + ": expected 1, 2, 4 or 8, got '" + text + "'");
  return std::stoi(text);
}
}  // namespace

CLI::Option* add_msaa(CLI::App& app, const std::string& flag, std::optional<int>& value, const std::string& help) {
  return option(
      app, flag, [&value, flag](const std::string& t) { value = msaa_of(t, flag); }, "N",
      described(help, "1, 2, 4 or 8", ""));
}

CLI::Option* add_msaa_list(CLI::App& app, const std::string& flag, std::vector<int>& value, const std::string& help) {
  std::string shown;
  for (int v : value) shown += (shown.empty() ? "" : ",") + std::to_string(v);
  return option(
      app, flag,
      [&value, flag](const std::string& t) {
        value.clear();
        for (const std::string& item : split_list(t, flag, kMaxListItems)) value.push_back(msaa_of(item, flag));
      },
      "LIST", described(help, "each 1, 2, 4 or 8", shown));
}

CLI::Option* add_render_scale(CLI::App& app, const std::string& flag, std::optional<float>& value,
                              const std::string& help) {
  const NumberRange range{engine::kMinRenderScale, engine::kMaxRenderScale};
  return option(
      app, flag,
      [&value, flag, range](const std::string& t) {
        if (t == "auto") {
          value.reset();
          return;
        }
        try {
          value = float(parse_number(t, flag, range));
        } catch (const UsageError&) {
          throw UsageError(flag + ": expected auto or a scale from " + range_text(range) + ", got '" + t + "'");
        }
      },
      "auto|S", described(help, "S from " + range_text(range), value ? number_text(*value) : "auto"));
}

CLI::Option* add_number_list(CLI::App& app, const std::string& flag, std::vector<double>& value, NumberRange each,
                             const std::string& form, const std::string& help, size_t max_items) {
  std::string shown;
  for (double v : value) shown += (shown.empty() ? "" : ",") + number_text(v);
  return option(
      app, flag,
      [&value, flag, each, max_items](const std::string& t) {
        value.clear();
        for (const std::string& item : split_list(t, flag, max_items)) value.push_back(parse_number(item, flag, each));
      },
      form, described(help, "each " + range_text(each), shown));
}

CLI::Option* add_whole_list(CLI::App& app, const std::string& flag, std::vector<long long>& value, WholeRange each,
                            const std::string& form, const std::string& help) {
  std::string shown;
  for (long long v : value) shown += (shown.empty() ? "" : ",") + std::to_string(v);
  return option(
      app, flag,
      [&value, flag, each](const std::string& t) {
        value.clear();
        for (const std::string& item : split_list(t, flag, kMaxListItems))
          value.push_back(parse_whole(item, flag, each));
      },
      form, described(help, "each " + range_text(each) + ", at most " + std::to_string(kMaxListItems), shown));
}

CLI::Option* add_db(CLI::App& app, std::optional<std::string>& value) {
  return add_text(app, "--db", value, "FILE|URI",
                  "session database: an SQLite file or postgresql://USER@HOST/DBNAME[?sslmode=...]\n"
                  "(default: $NEEDLE_DB, else $XDG_DATA_HOME or ~/.local/share, needle-sim/sessions.db)");
}

CLI::Option* add_flag(CLI::App& app, const std::string& flag, bool& value, const std::string& help) {
  return app.add_flag(flag, value, help);
}

}  // namespace needle::cli
