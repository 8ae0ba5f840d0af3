// Scenario files (haptics::load_scenario, which loads the robots' URDF and the tissue parameter
// sets they name): any input is a scenario or one of the readers' errors, nothing else.
#include "fuzz_input.hpp"
#include "haptics/model/urdf_loader.hpp"
#include "haptics/sim/scenario.hpp"
#include "structure.hpp"

NEEDLE_FUZZ_MUTATIONS(needle::fuzz::extreme_number, needle::fuzz::deep_json)

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  try {
    needle::haptics::load_scenario(needle::fuzz::write_input("scenarios/fuzz_input.json", data, size).string());
  } catch (const needle::haptics::ScenarioError&) {
  } catch (const needle::haptics::UrdfError&) {
  }
  return 0;
}
