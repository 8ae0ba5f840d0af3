// glTF assets (engine::load_gltf, through tinygltf): an input starting with the binary magic is
// read as a .glb, any other as a .gltf beside the shipped assets' buffers and images. Any input
// is a model or an engine::AssetError, nothing else.
#include <cstring>

#include "engine/gltf_loader.hpp"
#include "fuzz_input.hpp"
#include "structure.hpp"

NEEDLE_FUZZ_MUTATIONS(needle::fuzz::extreme_number, needle::fuzz::deep_json)

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const bool binary = size >= 4 && std::memcmp(data, "glTF", 4) == 0;
  try {
    needle::engine::load_gltf(needle::fuzz::write_input(binary ? "fuzz_input.glb" : "fuzz_input.gltf", data, size));
  } catch (const needle::engine::AssetError&) {
  }
  return 0;
}
