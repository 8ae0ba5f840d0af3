// Every number of a scenario file, an operator's hand and a tissue parameter set has a range
// (haptics/sim/scenario_limits.hpp, the tissue key table, io/input_limits.hpp): a number past it,
// 1e300 or -1e300 or a period of 1e-300, is one line naming the file, the JSON pointer, the
// range and the value, never a run that hangs or ends in NaN. The expected ranges are written
// here as docs/HAPTICS.md and docs/TISSUE.md state them.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "haptics/sim/scenario.hpp"
#include "robot_fixtures.hpp"
#include "scenario_files.hpp"

namespace needle::haptics {
namespace {

using nlohmann::json;
namespace fs = std::filesystem;

// A shipped scenario with its files' paths made absolute, so that a copy loads from anywhere.
json shipped(const std::string& name) {
  json s = test::read_json(test::asset("assets/scenarios/" + name + ".json"));
  for (const char* key : {"master_urdf", "virtual_urdf"})
    s[key] = test::asset("assets/robots/" + fs::path(s[key].get<std::string>()).filename().string());
  if (s.contains("tissue") && s["tissue"].contains("layers"))
    for (json& layer : s["tissue"]["layers"])
      if (layer.contains("parameters"))
        layer["parameters"] =
            test::asset("assets/tissues/" + fs::path(layer["parameters"].get<std::string>()).filename().string());
  return s;
}

// Where the running test writes its scenario.
std::string scenario_file() { return test::own_file("scenario.json"); }

// The error of loading `scenario` written as scenario_file(): "FILE: " and the rest, or "no error".
std::string error_of(const json& scenario) {
  const std::string file = scenario_file();
  std::ofstream(file) << scenario.dump(1);
  try {
    load_scenario(file);
  } catch (const ScenarioError& e) {
    return e.what();
  }
  return "no error";
}

struct Case {
  const char* scenario;
  const char* pointer;
  double value;
  const char* range;  // as the error says it
};

TEST(ScenarioRanges, EveryNumberPastItsRangeNamesTheFileThePointerTheRangeAndTheValue) {
  const Case cases[] = {
      {"holonomic_sphere", "/robot_base_in_world_m/0", 1e300, "[-10, 10] m"},
      {"holonomic_sphere", "/period_s", 1e300, "[0.0001, 0.004] s"},
      {"holonomic_sphere", "/period_s", 1e-300, "[0.0001, 0.004] s"},  // a tiny period: not a std:: message
      {"holonomic_sphere", "/duration_s", 1e300, "(0, 1800] s"},
      {"holonomic_sphere", "/q0_rad/2", -1e300, "[-6.28319, 6.28319] rad"},
      {"holonomic_sphere", "/gains/gpm/alpha", 1e300, "(0, 2] kg"},
      {"holonomic_sphere", "/gains/gpm/xi", 1e300, "(0, 10000]"},
      {"holonomic_sphere", "/gains/gpm/omega", 1e300, "(0, 20000] rad/s"},
      {"holonomic_sphere", "/gains/switch_time_s", 1e300, "(0, 1] s"},
      {"holonomic_sphere", "/gains/force_scale", 1e300, "(0, 10]"},
      {"holonomic_sphere", "/gains/lateral_damping_Ns_per_m", 1e300, "[0, 500] N*s/m"},
      {"holonomic_sphere", "/gains/axial_damping_Ns_per_m", -1e300, "[0, 500] N*s/m"},
      {"holonomic_sphere", "/tool/mass_kg", 1e300, "[0, 1] kg"},
      {"holonomic_sphere", "/rigid/primitives/0/sphere/centre/0", 1e300, "[-10, 10] m"},
      {"holonomic_sphere", "/rigid/primitives/0/sphere/radius", 1e300, "[1e-06, 1] m"},
      {"holonomic_sphere", "/hand/mass_kg", 1e300, "(0, 10] kg"},
      {"holonomic_sphere", "/hand/damping_Ns_per_m", 1e300, "[0, 200] N*s/m"},
      {"holonomic_sphere", "/hand/stiffness_N_per_m", 1e300, "[0, 5000] N/m"},
      {"holonomic_sphere", "/hand/grip_length_m", 1e300, "(0, 0.2] m"},
      {"holonomic_sphere", "/hand/waypoints/1/p/2", 1e300, "[-10, 10] m"},
      {"holonomic_sphere", "/hand/waypoints/1/dir/0", 1e300, "[-1e+06, 1e+06]"},
      {"holonomic_sphere", "/sensor/bias_N/1", 1e300, "[-10, 10] N"},
      {"holonomic_sphere", "/sensor/force_noise_N", 1e300, "[0, 10] N"},
      {"holonomic_sphere", "/sensor/bandwidth_Hz", 1e300, "(0, 10000] Hz"},
      {"holonomic_sphere", "/device/force_limit_N", 1e300, "(0, 100] N"},
      {"holonomic_sphere", "/energy_bound_J", 1e300, "(0, 100] J"},
      {"epidural", "/gains/nonholonomic/alpha", 1e300, "(0, 5000] 1/s"},
      {"epidural", "/gains/nonholonomic/beta", 1e300, "(0, 2.5e+07] 1/s^2"},
      {"epidural", "/gains/lateral_stiffness_N_per_m", 1e300, "[0, 100000] N/m"},
      {"epidural", "/gains/axial_stiffness_N_per_m", 1e300, "[0, 100000] N/m"},
      {"epidural", "/tissue/stick/stiffness_N_per_m", 1e300, "(0, 1e+06] N/m"},
      {"epidural", "/tissue/stick/band_mps", 1e300, "(0, 0.1] m/s"},
      {"epidural", "/tissue/layers/0/shape/slab/point/2", 1e300, "[-10, 10] m"},
      {"epidural", "/tissue/layers/0/shape/slab/normal/2", 1e300, "[-1e+06, 1e+06]"},
      {"epidural", "/tissue/layers/0/shape/slab/thickness_m", 1e300, "[1e-06, 1] m"},
      {"epidural", "/tissue/layers/4/shape/box/min/0", -1e300, "[-10, 10] m"},
  };
  for (const Case& c : cases) {
    json s = shipped(c.scenario);
    s[json::json_pointer(c.pointer)] = c.value;
    const std::string file = scenario_file();
    char value[32];
    std::snprintf(value, sizeof value, "%g", c.value);
    EXPECT_EQ(error_of(s), file + ": " + c.pointer + ": must be in " + c.range + ", got " + value) << c.pointer;
  }
}

TEST(ScenarioRanges, SubstepsThatWouldHangTheRunAreRefused) {
  for (const char* key : {"/master_substeps", "/virtual_substeps"}) {
    json s = shipped("holonomic_sphere");
    s[json::json_pointer(key)] = 1000000;
    EXPECT_EQ(error_of(s), scenario_file() + ": " + key + ": expected a whole number from 1 to 100");
  }
}

TEST(ScenarioRanges, TheShippedScenariosAreInsideEveryRange) {
  for (const char* name : {"holonomic_sphere", "nonholonomic_needle", "tissue_block_layers", "liver_biopsy",
                           "lumbar_epidural", "epidural"}) {
    EXPECT_EQ(error_of(shipped(name)), "no error") << name;
  }
}

TEST(ScenarioRanges, ALayersMechanicsPastTheirRangeNameTheParameterSetOrTheScenario) {
  // In a parameter set file: the error names that file and the number's pointer in it.
  json set = test::read_json(test::asset("assets/tissues/skin.json"));
  set["stiffness_N_per_m"]["value"] = 1e300;
  const std::string set_file = test::own_file("skin.json");
  std::ofstream(set_file) << set.dump(1);
  json s = shipped("epidural");
  s["tissue"]["layers"][0]["parameters"] = set_file;
  const std::string file = scenario_file();
  EXPECT_EQ(error_of(s), set_file + ": /stiffness_N_per_m/value: must be in [0, 10000] N/m, got 1e+300");

  // Inline, each key: the scenario and the layer's pointer.
  const std::pair<const char*, const char*> keys[] = {
      {"stiffness_N_per_m", "[0, 10000] N/m"}, {"stiffness2_N_per_m2", "[0, 1.2e+07] N/m^2"},
      {"puncture_force_N", "[0, 100] N"},      {"cutting_force_N", "[0, 30] N"},
      {"friction_N_per_m", "[0, 5000] N/m"},   {"static_friction_N_per_m", "[0, 5000] N/m"},
      {"damping_Ns_per_m", "[0, 1000] N*s/m"}};
  for (const auto& [key, range] : keys) {
    json inline_layer = shipped("epidural");
    json& layer = inline_layer["tissue"]["layers"][0];
    layer.erase("parameters");
    layer[key] = 1e300;
    EXPECT_EQ(error_of(inline_layer), file + ": /tissue/layers/0/" + key + ": must be in " + range + ", got 1e+300")
        << key;
  }
  json acoustic = shipped("epidural");
  json& layer = acoustic["tissue"]["layers"][0];
  layer.erase("parameters");
  layer["ultrasound"] = {{"impedance_MRayl", 1e300},
                         {"attenuation_dB_per_cm_MHz", 1.0},
                         {"echogenicity", 0.5},
                         {"scatterer_density", 0.5}};
  EXPECT_EQ(error_of(acoustic),
            file + ": /tissue/layers/0/ultrasound/impedance_MRayl: must be in [0, 100] MRayl, got 1e+300");
}

TEST(ScenarioRanges, NotANumberIsNotJson) {
  const std::string file = scenario_file();
  error_of(shipped("holonomic_sphere"));
  std::ifstream in(file);
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::string period = "\"period_s\": 0.002";
  ASSERT_NE(text.find(period), std::string::npos);
  text.replace(text.find(period), period.size(), "\"period_s\": NaN");
  std::ofstream(file) << text;
  try {
    load_scenario(file);
    ADD_FAILURE() << "NaN loaded";
  } catch (const ScenarioError& e) {
    EXPECT_EQ(std::string(e.what()).rfind(file + ": /: not valid JSON: ", 0), 0u) << e.what();
  }
}

}  // namespace
}  // namespace needle::haptics
