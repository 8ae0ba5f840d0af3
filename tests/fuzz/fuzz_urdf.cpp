// Robot descriptions (haptics::parse_robot_urdf, through urdfdom): any input is a model or a
// haptics::UrdfError, nothing else; urdfdom's own messages are captured, never printed.
#include "haptics/model/urdf_loader.hpp"
#include "structure.hpp"

NEEDLE_FUZZ_MUTATIONS(needle::fuzz::extreme_number, needle::fuzz::deep_xml)

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  try {
    needle::haptics::parse_robot_urdf(std::string(reinterpret_cast<const char*>(data), size), "fuzz_input.urdf");
  } catch (const needle::haptics::UrdfError&) {
  }
  return 0;
}
