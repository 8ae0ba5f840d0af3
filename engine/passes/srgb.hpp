// The sRGB transfer function (IEC 61966-2-1). The targets are UNORM images that hold
// sRGB-encoded values (docs/RENDERING.md, "Colour"): what is computed in linear light (the
// clear colour, ImGui's vertex colours meant as linear) is encoded once on the CPU here.
#pragma once

#include <cmath>

namespace needle::engine {

inline float srgb_encode(float linear) {
  return linear <= 0.0031308f ? linear * 12.92f : 1.055f * std::pow(linear, 1.0f / 2.4f) - 0.055f;
}

inline float srgb_decode(float encoded) {
  return encoded <= 0.04045f ? encoded / 12.92f : std::pow((encoded + 0.055f) / 1.055f, 2.4f);
}

}  // namespace needle::engine
