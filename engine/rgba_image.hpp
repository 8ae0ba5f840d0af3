// 8-bit RGBA pixels in memory and their PNG files.
#pragma once

#include <cstdint>
#include <filesystem>
#include <vector>

namespace needle::engine {

struct RgbaImage {
  uint32_t width = 0;
  uint32_t height = 0;
  std::vector<uint8_t> pixels;  // row-major, top row first, 4 bytes a pixel

  const uint8_t* at(uint32_t x, uint32_t y) const { return &pixels[(size_t(y) * width + x) * 4]; }
};

// Makes the file's folder, encodes and writes the file whole (io::write_file); throws
// std::runtime_error (io::WriteError for the write) naming the file on failure.
void write_png(const std::filesystem::path& file, const RgbaImage& image);
RgbaImage read_png(const std::filesystem::path& file);

}  // namespace needle::engine
