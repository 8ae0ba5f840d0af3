// Strict reading of a JSON document with errors that point at the culprit:
// "FILE: /json/pointer: what is wrong", thrown as `Error`. Unknown keys are errors, numbers
// must be finite, strings non-empty and without NUL. Header-only: scene, scenario, task and tissue files all
// read through it, from libraries that do not link each other.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <iterator>
#include <nlohmann/json.hpp>
#include <span>
#include <string>

namespace needle::io {

// The text of `file`; Error("FILE: /: what") when it is not a readable regular file.
template <typename Error>
std::string read_text_file(const std::filesystem::path& file) {
  std::error_code ec;
  const auto status = std::filesystem::status(file, ec);
  if (!std::filesystem::exists(status)) throw Error(file.string() + ": /: file not found");
  if (std::filesystem::is_directory(status)) throw Error(file.string() + ": /: is a folder, not a file");
  if (!std::filesystem::is_regular_file(status)) throw Error(file.string() + ": /: not a regular file");
  std::ifstream in(file, std::ios::binary);
  if (!in) throw Error(file.string() + ": /: cannot open the file for reading");
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (in.bad()) throw Error(file.string() + ": /: cannot be read");
  return text;
}

// The document in `text`, read from `label` (a file name); Error("LABEL: /: not valid JSON: ...").
template <typename Error>
nlohmann::json parse_json(const std::string& text, const std::string& label) {
  try {
    return nlohmann::json::parse(text);
  } catch (const nlohmann::json::exception& e) {
    throw Error(label + ": /: not valid JSON: " + e.what());
  }
}

// The document in `file`; Error("FILE: /: what") when it is not a readable regular file or not JSON.
template <typename Error>
nlohmann::json read_json_file(const std::filesystem::path& file) {
  return parse_json<Error>(read_text_file<Error>(file), file.string());
}

template <typename Error>
class StrictJsonReader {
 public:
  using json = nlohmann::json;
  explicit StrictJsonReader(std::string file) : file_(std::move(file)) {}

  [[noreturn]] void fail(const std::string& pointer, const std::string& what) const {
    throw Error(file_ + ": " + (pointer.empty() ? "/" : pointer) + ": " + what);
  }

  // Checks `value` is an object with no keys but `allowed`.
  void object(const json& value, const std::string& at, std::span<const char* const> allowed) const {
    if (!value.is_object()) fail(at, "expected an object, got " + std::string(value.type_name()));
    for (const auto& item : value.items()) {
      const std::string& key = item.key();  // not a structured binding: clang before 16 cannot capture one
      if (std::none_of(allowed.begin(), allowed.end(), [&](const char* k) { return key == k; })) {
        std::string keys;
        for (const char* k : allowed) keys += (keys.empty() ? "" : ", ") + std::string(k);
        fail(at + (json::json_pointer() / key).to_string(), "unknown key (allowed: " + keys + ")");
      }
    }
  }
  void object(const json& value, const std::string& at, std::initializer_list<const char*> allowed) const {
    object(value, at, std::span<const char* const>(allowed.begin(), allowed.size()));
  }

  const json& member(const json& value, const std::string& at, const char* key) const {
    if (!value.contains(key)) fail(at + "/" + key, "missing");
    return value[key];
  }

  double number(const json& value, const std::string& at) const {
    if (!value.is_number()) fail(at, "expected a number, got " + std::string(value.type_name()));
    const double x = value.get<double>();
    if (!std::isfinite(x)) fail(at, "not a finite number");
    return x;
  }

  double positive(const json& value, const std::string& at) const {
    const double x = number(value, at);
    if (!(x > 0.0)) fail(at, "must be > 0, got " + std::to_string(x));
    return x;
  }

  double non_negative(const json& value, const std::string& at) const {
    const double x = number(value, at);
    if (x < 0.0) fail(at, "must be >= 0, got " + std::to_string(x));
    return x;
  }

  // A number in [lo, hi], said as `range` in the error ("[0, 0.5]", "(0, 1] m", ...).
  double in_range(const json& value, const std::string& at, double lo, double hi, const std::string& range) const {
    const double x = number(value, at);
    if (!(x >= lo && x <= hi)) fail(at, "must be in " + range + ", got " + std::to_string(x));
    return x;
  }

  // A whole number in [lo, hi].
  long long whole(const json& value, const std::string& at, long long lo, long long hi) const {
    const double x = number(value, at);
    if (x != std::floor(x) || x < double(lo) || x > double(hi))
      fail(at, "expected a whole number from " + std::to_string(lo) + " to " + std::to_string(hi));
    return static_cast<long long>(x);
  }

  template <size_t N>
  std::array<double, N> numbers(const json& value, const std::string& at) const {
    if (!value.is_array() || value.size() != N) fail(at, "expected an array of " + std::to_string(N) + " numbers");
    std::array<double, N> v;
    for (size_t k = 0; k < N; ++k) v[k] = number(value[k], at + "/" + std::to_string(k));
    return v;
  }

  // A NUL ("\u0000") is refused: C strings, SQLite text and file names would end there.
  std::string string(const json& value, const std::string& at) const {
    if (!value.is_string() || value.get<std::string>().empty())
      fail(at, "expected a non-empty string, got " + std::string(value.type_name()));
    std::string text = value.get<std::string>();
    if (text.find('\0') != std::string::npos) fail(at, "contains a NUL character");
    return text;
  }

  // A path relative to `folder` that names an existing regular file, made canonical.
  std::filesystem::path existing_file(const json& value, const std::string& at, const std::filesystem::path& folder) const {
    const std::filesystem::path given = folder / string(value, at);
    std::error_code ec;
    const std::filesystem::path resolved = std::filesystem::weakly_canonical(given, ec);
    if (ec || !std::filesystem::is_regular_file(resolved, ec)) fail(at, "file not found: " + given.string());
    return resolved;
  }

  const std::string& file() const { return file_; }

 protected:
  std::string file_;
};

}  // namespace needle::io
