// Golden-image comparison with a stated tolerance; on failure the actual image and a diff image
// are written next to the test output. NEEDLE_UPDATE_GOLDENS=1 rewrites the golden instead
// (tests/README.md says when that is right).
#pragma once

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <string>

#include "engine/rgba_image.hpp"
#include "tests/support/test_paths.hpp"

namespace needle::test {

// A pixel differs when any of R, G, B differs by more than kChannelTolerance counts (of 255);
// an image matches when at most kMaxDifferingFraction of its pixels differ. The slack absorbs
// LLVM/Mesa code-generation differences in the last bit of shading and MSAA edge coverage; a
// moved camera, light, material or mesh changes far more pixels than that.
constexpr int kChannelTolerance = 8;
constexpr double kMaxDifferingFraction = 0.002;

// Largest R, G or B difference at byte offset i of two images of one size.
inline int channel_difference(const engine::RgbaImage& a, const engine::RgbaImage& b, size_t i) {
  int d = 0;
  for (size_t c = 0; c < 3; ++c) d = std::max(d, std::abs(int(a.pixels[i + c]) - int(b.pixels[i + c])));
  return d;
}

// Pixels of two images of one size that differ by more than kChannelTolerance.
inline size_t differing_pixels(const engine::RgbaImage& a, const engine::RgbaImage& b) {
  size_t differing = 0;
  for (size_t i = 0; i < a.pixels.size(); i += 4) differing += channel_difference(a, b, i) > kChannelTolerance;
  return differing;
}

inline ::testing::AssertionResult matches_golden(const engine::RgbaImage& actual, const std::string& name) {
  namespace fs = std::filesystem;
  const fs::path golden_path = test::source_dir() / "tests" / "golden" / (name + ".png");
  const fs::path out_dir = test::output_dir() / "golden";
  const char* update = std::getenv("NEEDLE_UPDATE_GOLDENS");
  if (update && std::string(update) == "1") {
    engine::write_png(golden_path, actual);
    return ::testing::AssertionSuccess() << "updated " << golden_path;
  }
  if (!fs::exists(golden_path)) {
    engine::write_png(out_dir / (name + ".actual.png"), actual);
    return ::testing::AssertionFailure() << "no golden " << golden_path << " (see tests/README.md to create it)";
  }
  engine::RgbaImage golden = engine::read_png(golden_path);
  if (golden.width != actual.width || golden.height != actual.height) {
    engine::write_png(out_dir / (name + ".actual.png"), actual);
    return ::testing::AssertionFailure() << "size " << actual.width << "x" << actual.height << " but golden is "
                                         << golden.width << "x" << golden.height;
  }
  engine::RgbaImage diff{actual.width, actual.height, std::vector<uint8_t>(actual.pixels.size(), 0)};
  size_t differing = 0;
  int worst = 0;
  for (size_t i = 0; i < actual.pixels.size(); i += 4) {
    const int d = channel_difference(actual, golden, i);
    worst = std::max(worst, d);
    bool bad = d > kChannelTolerance;
    differing += bad;
    // Diff image: differing pixels red, scaled by size; matching ones a dim copy of the golden.
    diff.pixels[i] = bad ? uint8_t(std::min(255, 128 + d)) : uint8_t(golden.pixels[i] / 4);
    diff.pixels[i + 1] = bad ? 0 : uint8_t(golden.pixels[i + 1] / 4);
    diff.pixels[i + 2] = bad ? 0 : uint8_t(golden.pixels[i + 2] / 4);
    diff.pixels[i + 3] = 255;
  }
  size_t pixels = actual.pixels.size() / 4;
  if (double(differing) <= kMaxDifferingFraction * double(pixels)) {
    return ::testing::AssertionSuccess() << differing << " pixels differ";
  }
  engine::write_png(out_dir / (name + ".actual.png"), actual);
  engine::write_png(out_dir / (name + ".diff.png"), diff);
  return ::testing::AssertionFailure() << name << ": " << differing << " of " << pixels
                                       << " pixels differ by more than " << kChannelTolerance << " (worst " << worst
                                       << "); actual and diff in " << out_dir;
}

}  // namespace needle::test
