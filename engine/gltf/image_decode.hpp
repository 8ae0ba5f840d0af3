// A glTF image's bytes decoded (PNG, JPEG: what stb_image reads), its size checked from the header
// before any pixel is: a file that declares a huge image is refused, not decoded into gigabytes.
#pragma once

#include <string>

namespace tinygltf {
struct Image;
}

namespace needle::engine {

// Design value: the largest side of a texture, 8192 pixels. Vulkan guarantees 4096 (the minimum
// maxImageDimension2D) and desktop GPUs offer 16384; a tissue or needle texture needs far less,
// and 8192 x 8192 RGBA is 256 MB decoded, the most an asset may cost.
inline constexpr int kMaxTextureSide = 8192;

// (encoded bytes) => `image` decoded to 8 or 16 bits a channel (tinygltf's LoadImageData), or
// false with `err` saying why: not an image, or a side over kMaxTextureSide.
bool decode_image(tinygltf::Image* image, int index, std::string* err, std::string* warn, const unsigned char* bytes,
                  int size);

}  // namespace needle::engine
