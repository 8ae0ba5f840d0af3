// Strict reading of a JSON document with errors that point at the culprit:
// "FILE: /json/pointer: what is wrong", thrown as `Error`. Unknown keys are errors, numbers
// must be finite (and in their key's range where one is given), strings non-empty and without
// NUL; a file must be a regular one of at most kMaxTextFileBytes (io/file_read.hpp), nested at
// most kMaxNestingDepth deep and with no key twice in an object (io/json_text.hpp). A template
// on the error type: scene, scenario, task and tissue files all read through it, from libraries
// that do not link each other.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <initializer_list>
#include <nlohmann/json.hpp>
#include <span>
#include <stdexcept>
#include <string>

#include "io/file_read.hpp"
#include "io/input_limits.hpp"
#include "io/json_text.hpp"

namespace needle::io {

// The text of `file`; Error("FILE: /: what") when it is not a readable regular file (read_text).
template <typename Error>
std::string read_text_file(const std::filesystem::path& file) {
  std::string problem;
  std::string text = read_text(file, problem);
  if (!problem.empty()) throw Error(file.string() + ": /: " + problem);
  return text;
}

// The document in `text`, read from `label` (a file name); Error("LABEL: /POINTER: what"), as
// "LABEL: /: not valid JSON: ...".
template <typename Error>
nlohmann::json parse_json(const std::string& text, const std::string& label) {
  try {
    return parse_json_text(text);
  } catch (const JsonTextError& e) {
    throw Error(label + ": " + e.pointer + ": " + e.what());
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

  // A number in `range`: "FILE: /pointer: must be in (0, 1800] s, got 1e+300" when it is not.
  double in_range(const json& value, const std::string& at, const Range& range) const {
    const double x = number(value, at);
    if (!range.contains(x)) fail(at, "must be in " + range.text() + ", got " + number_text(x));
    return x;
  }

  // N numbers, each in `range`.
  template <size_t N>
  std::array<double, N> numbers_in(const json& value, const std::string& at, const Range& range) const {
    const std::array<double, N> v = numbers<N>(value, at);
    for (size_t k = 0; k < N; ++k)
      if (!range.contains(v[k]))
        fail(at + "/" + std::to_string(k), "must be in " + range.text() + ", got " + number_text(v[k]));
    return v;
  }

  // A position in the world: three numbers within kWorldExtent_m.
  std::array<double, 3> position(const json& value, const std::string& at) const {
    return numbers_in<3>(value, at, kWorldCoordinateRange);
  }

  // A direction as given (its reader normalizes it): three numbers within kMaxDirectionComponent,
  // not all (nearly) zero.
  std::array<double, 3> direction(const json& value, const std::string& at) const {
    const std::array<double, 3> v = numbers_in<3>(value, at, kDirectionComponentRange);
    if (!(std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]) >= 1e-9)) fail(at, "must not be the zero vector");
    return v;
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
  std::filesystem::path existing_file(const json& value, const std::string& at,
                                      const std::filesystem::path& folder) const {
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
