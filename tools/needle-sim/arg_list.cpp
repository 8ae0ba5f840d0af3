#include "arg_list.hpp"

#include <charconv>
#include <cmath>
#include <filesystem>

#include "command.hpp"
#include "engine/scene_renderer.hpp"

namespace needle::cli {

ArgList::ArgList(std::vector<std::string> args) : args_(std::move(args)), used_(args_.size(), false) {}

std::optional<std::string> ArgList::value(const std::string& flag) {
  std::optional<std::string> found;
  for (size_t i = 0; i < args_.size(); ++i) {
    if (used_[i]) continue;
    std::string v;
    if (args_[i] == flag) {
      if (i + 1 >= args_.size() || used_[i + 1]) throw UsageError(flag + " needs a value");
      v = args_[i + 1];
      used_[i] = used_[i + 1] = true;
      ++i;
    } else if (args_[i].rfind(flag + "=", 0) == 0) {
      v = args_[i].substr(flag.size() + 1);
      used_[i] = true;
    } else {
      continue;
    }
    if (found) throw UsageError(flag + " given more than once");
    found = v;
  }
  return found;
}

std::string ArgList::required(const std::string& flag) {
  auto v = value(flag);
  if (!v) throw UsageError("missing required " + flag);
  return *v;
}

bool ArgList::flag(const std::string& flag) {
  bool found = false;
  for (size_t i = 0; i < args_.size(); ++i) {
    if (!used_[i] && args_[i] == flag) {
      used_[i] = true;
      found = true;
    }
  }
  return found;
}

void ArgList::finish() const {
  std::string unknown;
  for (size_t i = 0; i < args_.size(); ++i) {
    if (!used_[i]) unknown += (unknown.empty() ? "" : " ") + args_[i];
  }
  if (!unknown.empty()) throw UsageError("unexpected argument(s): " + unknown);
}

bool ArgList::wants_help() const {
  for (const auto& a : args_) {
    if (a == "--help" || a == "-h") return true;
  }
  return false;
}

double parse_number(const std::string& text, const std::string& flag) {
  double v = 0;
  const char* end = text.data() + text.size();
  auto [ptr, ec] = std::from_chars(text.data(), end, v);
  if (ec != std::errc() || ptr != end || !std::isfinite(v)) {
    throw UsageError(flag + ": expected a number, got '" + text + "'");
  }
  return v;
}

long long parse_whole(const std::string& text, const std::string& flag, long long lo, long long hi) {
  const double v = parse_number(text, flag);
  if (!(v >= double(lo) && v <= double(hi)) || v != std::floor(v))
    throw UsageError(flag + ": expected a whole number from " + std::to_string(lo) + " to " + std::to_string(hi) + ", got '" +
                     text + "'");
  return static_cast<long long>(v);
}

std::optional<std::string> output_file(ArgList& args, const std::string& flag) {
  std::optional<std::string> file = args.value(flag);
  if (!file) return file;
  const std::filesystem::path folder = std::filesystem::absolute(*file).parent_path();
  if (!std::filesystem::is_directory(folder)) throw UsageError(flag + ": folder " + folder.string() + " does not exist");
  return file;
}

int parse_msaa(const std::string& text, const std::string& flag) {
  double v = parse_number(text, flag);
  if (v != 1 && v != 2 && v != 4 && v != 8) throw UsageError(flag + ": expected 1, 2, 4 or 8, got '" + text + "'");
  return int(v);
}

std::optional<float> parse_render_scale(const std::string& text, const std::string& flag) {
  if (text == "auto") return std::nullopt;
  const double v = parse_number(text, flag);
  if (!(v >= engine::kMinRenderScale && v <= engine::kMaxRenderScale))
    throw UsageError(flag + ": expected auto or a scale in [0.25, 1], got '" + text + "'");
  return float(v);
}

std::vector<double> parse_number_list(const std::string& text, const std::string& flag) {
  std::vector<double> out;
  size_t start = 0;
  while (true) {
    size_t comma = text.find(',', start);
    out.push_back(parse_number(text.substr(start, comma - start), flag));
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  return out;
}

engine::Extent parse_size(const std::string& text, const std::string& flag) {
  size_t x = text.find('x');
  if (x == std::string::npos) throw UsageError(flag + ": expected WxH, got '" + text + "'");
  auto parse_dim = [&](std::string_view s) {
    unsigned v = 0;
    auto [ptr, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
    if (ec != std::errc() || ptr != s.data() + s.size() || v == 0 || v > 16384) {
      throw UsageError(flag + ": expected WxH with each side in 1..16384, got '" + text + "'");
    }
    return v;
  };
  std::string_view all(text);
  return {parse_dim(all.substr(0, x)), parse_dim(all.substr(x + 1))};
}

void check_output_folder(const std::optional<std::string>& file, const std::string& flag) {
  if (!file) return;
  const std::filesystem::path folder = std::filesystem::absolute(*file).parent_path();
  if (!std::filesystem::is_directory(folder)) throw UsageError(flag + ": folder " + folder.string() + " does not exist");
}

}  // namespace needle::cli
