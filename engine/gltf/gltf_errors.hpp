// Error reporting shared by the glTF and scene loaders: "FILE: ELEMENT: what is wrong".
#pragma once

#include <string>

#include "engine/model.hpp"

namespace needle::engine {

[[noreturn]] inline void asset_fail(const std::string& file, const std::string& element, const std::string& what) {
  throw AssetError(file + ": " + element + ": " + what);
}

// "name[index]", the way glTF elements are named in messages.
inline std::string element_name(const char* array, size_t index) {
  return std::string(array) + "[" + std::to_string(index) + "]";
}

}  // namespace needle::engine
