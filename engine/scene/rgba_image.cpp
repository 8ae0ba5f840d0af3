#include "engine/rgba_image.hpp"

#include <stb_image.h>
#include <stb_image_write.h>

#include <stdexcept>
#include <string>

#include "io/file_write.hpp"

namespace needle::engine {

void write_png(const std::filesystem::path& file, const RgbaImage& image) {
  if (image.pixels.size() != size_t(image.width) * image.height * 4) {
    throw std::runtime_error(file.string() + ": image data does not match its size");
  }
  if (file.has_parent_path()) io::make_folder(file.parent_path());
  // Encoded in memory, then written whole and checked (a full disk is an error, not an empty PNG).
  std::string png;
  const auto append = [](void* to, void* data, int size) {
    static_cast<std::string*>(to)->append(static_cast<char*>(data), size_t(size));
  };
  if (!stbi_write_png_to_func(append, &png, int(image.width), int(image.height), 4, image.pixels.data(),
                              int(image.width * 4))) {
    throw std::runtime_error(file.string() + ": cannot encode the PNG");
  }
  io::write_file(file, png);
}

RgbaImage read_png(const std::filesystem::path& file) {
  int w = 0, h = 0, channels = 0;
  stbi_uc* data = stbi_load(file.c_str(), &w, &h, &channels, 4);
  if (!data) throw std::runtime_error(file.string() + ": cannot read PNG (" + stbi_failure_reason() + ")");
  RgbaImage image{uint32_t(w), uint32_t(h), std::vector<uint8_t>(data, data + size_t(w) * h * 4)};
  stbi_image_free(data);
  return image;
}

}  // namespace needle::engine
