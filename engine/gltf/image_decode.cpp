#include "engine/gltf/image_decode.hpp"

#include <stb_image.h>
#include <tiny_gltf.h>

namespace needle::engine {

bool decode_image(tinygltf::Image* image, int index, std::string* err, std::string* warn, const unsigned char* bytes,
                  int size) {
  int width = 0, height = 0, channels = 0;
  const std::string name = "image[" + std::to_string(index) + "]: ";
  if (!stbi_info_from_memory(bytes, size, &width, &height, &channels)) {
    if (err) *err = name + "not an image stb_image reads (" + stbi_failure_reason() + ")";
    return false;
  }
  if (width > kMaxTextureSide || height > kMaxTextureSide) {
    if (err)
      *err = name + "a " + std::to_string(width) + "x" + std::to_string(height) + " image, over the " +
             std::to_string(kMaxTextureSide) + " pixels a side a texture may have";
    return false;
  }
  return tinygltf::LoadImageData(image, index, err, warn, 0, 0, bytes, size, nullptr);
}

}  // namespace needle::engine
