// A picture's size in pixels: what the engine's public API takes instead of a backend type.
#pragma once

#include <cstdint>

namespace needle::engine {

struct Extent {
  uint32_t width = 0;
  uint32_t height = 0;
};

}  // namespace needle::engine
