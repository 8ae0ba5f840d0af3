// Scene files (engine::load_scene): any input is a scene or an engine::AssetError, nothing else.
#include "engine/scene.hpp"
#include "fuzz_input.hpp"
#include "structure.hpp"

NEEDLE_FUZZ_MUTATIONS(needle::fuzz::extreme_number, needle::fuzz::deep_json)

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  try {
    needle::engine::load_scene(needle::fuzz::write_input("scenes/fuzz_input.json", data, size));
  } catch (const needle::engine::AssetError&) {
  }
  return 0;
}
