// Strict reading of a JSON document with errors that point at the culprit:
// "FILE: /json/pointer: what is wrong", thrown as `Error`. Unknown keys are errors, numbers
// must be finite, strings non-empty. Header-only, so readers outside the engine (task files in
// ui/) use it without linking the engine.
#pragma once

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <nlohmann/json.hpp>
#include <string>

namespace needle::engine {

template <typename Error>
class StrictJsonReader {
 public:
  using json = nlohmann::json;
  explicit StrictJsonReader(std::string file) : file_(std::move(file)) {}

  [[noreturn]] void fail(const std::string& pointer, const std::string& what) const {
    throw Error(file_ + ": " + (pointer.empty() ? "/" : pointer) + ": " + what);
  }

  // Checks `value` is an object with no keys but `allowed`.
  void object(const json& value, const std::string& at, std::initializer_list<const char*> allowed) const {
    if (!value.is_object()) fail(at, "expected an object, got " + std::string(value.type_name()));
    for (const auto& [key, _] : value.items()) {
      if (std::none_of(allowed.begin(), allowed.end(), [&](const char* k) { return key == k; })) {
        std::string keys;
        for (const char* k : allowed) keys += (keys.empty() ? "" : ", ") + std::string(k);
        fail(at + (json::json_pointer() / key).to_string(), "unknown key (allowed: " + keys + ")");
      }
    }
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

  std::string string(const json& value, const std::string& at) const {
    if (!value.is_string() || value.get<std::string>().empty())
      fail(at, "expected a non-empty string, got " + std::string(value.type_name()));
    return value.get<std::string>();
  }

 protected:
  std::string file_;
};

}  // namespace needle::engine
