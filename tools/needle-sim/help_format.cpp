#include "help_format.hpp"

#include <CLI/Formatter.hpp>
#include <algorithm>
#include <functional>
#include <vector>

namespace needle::cli {

std::string full_name(const CLI::App* app) {
  std::string name = app->get_name();
  for (const CLI::App* p = app->get_parent(); p; p = p->get_parent()) name = p->get_name() + " " + name;
  return name;
}

namespace {

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

}  // namespace

std::shared_ptr<CLI::Formatter> help_formatter() {
  auto formatter = std::make_shared<SynopsisFormatter>();
  formatter->column_width(22);
  return formatter;
}

}  // namespace needle::cli
