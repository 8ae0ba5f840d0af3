// Tissue in scenario files and the shipped parameter sets (assets/tissues/*.json): what loads,
// and the errors for what must not, each naming the file, the JSON pointer and what was expected.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <regex>

#include "haptics/sim/scenario.hpp"
#include "haptics/tissue/kinematic_insertion.hpp"
#include "robot_fixtures.hpp"
#include "scenario_files.hpp"

namespace needle::haptics {
namespace {

using Eigen::Vector3d;
using nlohmann::json;
namespace fs = std::filesystem;

// The thesis's needle scenario with `tissue` replaced (and the keys of `more` added), written where
// the test's files are.
std::string scenario_with_tissue(const json& tissue, const json& more = json::object()) {
  json s = test::read_json(test::asset("assets/scenarios/nonholonomic_needle.json"));
  s["master_urdf"] = test::asset("assets/robots/master_omni.urdf");
  s["virtual_urdf"] = test::asset("assets/robots/virtual_needle_robot.urdf");
  s["tissue"] = tissue;
  s.update(more);
  const std::string path = test::own_file("scenario.json");
  std::ofstream(path) << s.dump(1);
  return path;
}

// The error's text after "FILE: ", or "no error".
std::string error_of(const std::string& path) {
  try {
    load_scenario(path);
  } catch (const ScenarioError& e) {
    const std::string what = e.what();
    return what.rfind(path + ": ", 0) == 0 ? what.substr(path.size() + 2) : what;
  }
  return "no error";
}

json slab(double top, double thickness) {
  return {{"slab", {{"point", {0.4, 0.0, top}}, {"normal", {0.0, 0.0, 1.0}}, {"thickness_m", thickness}}}};
}

json two_slabs() {
  return {
      {"layers",
       {{{"name", "skin"}, {"shape", slab(0.05, 0.003)}, {"stiffness_N_per_m", 200}, {"puncture_force_N", 1.0}},
        {{"name", "fat"}, {"shape", slab(0.047, 0.01)}, {"friction_N_per_m", 20}, {"static_friction_N_per_m", 30}}}}};
}

TEST(TissueFiles, TheShippedLayeredScenariosLoad) {
  const Scenario block = load_scenario(test::asset("assets/scenarios/tissue_block_layers.json"));
  ASSERT_EQ(block.scene.tissue.layer_count(), 4);
  EXPECT_EQ(block.scene.tissue.layer(0).name, "skin");
  EXPECT_TRUE(block.scene.tissue.layer(3).mechanics.rigid);
  // The block of tools/asset-gen (skin 0 to −2 mm, ..., bone −40 to −50 mm) at (0.33, 0, 0.07) m in the world.
  EXPECT_EQ(block.scene.tissue.layer_at(Vector3d(0.33, 0.0, 0.069) - block.base_in_world), 0);
  EXPECT_EQ(block.scene.tissue.layer_at(Vector3d(0.33, 0.0, 0.060) - block.base_in_world), 1);
  EXPECT_EQ(block.scene.tissue.layer_at(Vector3d(0.33, 0.0, 0.040) - block.base_in_world), 2);
  EXPECT_EQ(block.scene.tissue.layer_at(Vector3d(0.33, 0.0, 0.025) - block.base_in_world), 3);
  EXPECT_EQ(block.scene.tissue.layer_at(Vector3d(0.39, 0.0, 0.060) - block.base_in_world), -1);  // beside the block

  const Scenario epidural = load_scenario(test::asset("assets/scenarios/lumbar_epidural.json"));
  EXPECT_EQ(epidural.scene.tissue.layer_count(), 9);
  EXPECT_EQ(epidural.scene.tissue.layer(4).name, "ligamentum flavum");
  EXPECT_DOUBLE_EQ(epidural.scene.tissue.layer(4).mechanics.puncture_force_N, 5.0);

  const Scenario liver = load_scenario(test::asset("assets/scenarios/liver_biopsy.json"));
  EXPECT_EQ(liver.scene.tissue.layer_count(), 4);
  EXPECT_EQ(liver.scene.tissue.layer_at(Vector3d(0.4, 0, 0) - liver.base_in_world), 3);  // the liver, innermost
  EXPECT_EQ(liver.scene.tissue.layer_at(Vector3d(0.4, 0, 0.099) - liver.base_in_world), 0);
}

TEST(TissueFiles, EveryParameterSetLoadsAndEveryNumberCarriesItsSource) {
  int sets = 0;
  for (const auto& entry : fs::directory_iterator(test::asset("assets/tissues"))) {
    const json set = test::read_json(entry.path().string());
    json numbers = set;
    numbers.erase("ultrasound");
    numbers.update(set["ultrasound"]);  // what the set is to ultrasound: every number with its source too
    if (set.contains("injection")) {    // and to an injection
      numbers.erase("injection");
      numbers.update(set["injection"]);
    }
    for (const auto& [key, value] : numbers.items()) {
      if (key == "tissue" || key == "description" || key == "references") continue;
      ASSERT_TRUE(value.is_object()) << entry.path() << " " << key;
      const std::string source = value["source"].get<std::string>();
      EXPECT_TRUE(source.rfind("design value: ", 0) == 0 ||
                  set["references"].contains(source.substr(0, source.find(':'))))
          << entry.path() << " " << key << ": " << source;
    }
    const json tissue = {
        {"layers", {{{"name", "x"}, {"shape", slab(0.05, 0.01)}, {"parameters", entry.path().string()}}}}};
    EXPECT_EQ(error_of(scenario_with_tissue(tissue)), "no error") << entry.path();
    const LayerAcoustics acoustics =
        load_scenario(scenario_with_tissue(tissue)).scene.tissue.layer(0).acoustics.value();
    EXPECT_EQ(acoustics.impedance_MRayl, set["ultrasound"]["impedance_MRayl"]["value"].get<double>()) << entry.path();
    EXPECT_EQ(acoustics.echogenicity, set["ultrasound"]["echogenicity"]["value"].get<double>()) << entry.path();
    ++sets;
  }
  EXPECT_GE(sets, 8);  // skin, fat, muscle, ligament, flavum, dura, liver, bone at least
}

// The injection keys (docs/TISSUE.md, "The syringe") and the syringe that needs them: each bad value
// one line naming the file, the JSON pointer and what was expected.
TEST(TissueFiles, InjectionKeysAreCheckedAndASyringeNeedsThemOnEveryLayer) {
  json tissue = two_slabs();
  for (json& layer : tissue["layers"])
    layer["injection"] = {{"opening_pressure_Pa", 1e3}, {"resistance_Pa_s_per_m3", 1e9}};
  EXPECT_EQ(error_of(scenario_with_tissue(tissue, {{"syringe", {{"fluid", "air"}}}})), "no error");
  EXPECT_EQ(load_scenario(scenario_with_tissue(tissue, {{"syringe", {{"fluid", "air"}}}})).syringe->fluid,
            SyringeFluid::kAir);

  json bad = tissue;
  bad["layers"][1]["injection"]["opening_pressure_Pa"] = 2e6;
  EXPECT_EQ(error_of(scenario_with_tissue(bad)),
            "/tissue/layers/1/injection/opening_pressure_Pa: must be in [0, 1e+06] Pa, got 2e+06");
  bad = tissue;
  bad["layers"][0]["injection"].erase("resistance_Pa_s_per_m3");
  EXPECT_EQ(error_of(scenario_with_tissue(bad)), "/tissue/layers/0/injection/resistance_Pa_s_per_m3: missing");
  bad = tissue;
  bad["layers"][0]["injection"]["resistance_Pa_s_per_m3"] = -1.0;
  EXPECT_EQ(error_of(scenario_with_tissue(bad)),
            "/tissue/layers/0/injection/resistance_Pa_s_per_m3: must be in [0, 1e+15] Pa*s/m^3, got -1");

  // A syringe needs every soft layer's injection keys; a layer without is named.
  bad = tissue;
  bad["layers"][1].erase("injection");
  EXPECT_EQ(error_of(scenario_with_tissue(bad, {{"syringe", {{"fluid", "saline"}}}})),
            "/tissue/layers/1: \"fat\" has no injection parameters (\"injection\", in its parameter set or inline), "
            "which the syringe "
            "(/syringe) needs");
  EXPECT_EQ(error_of(scenario_with_tissue(tissue, {{"syringe", {{"fluid", "water"}}}})),
            "/syringe/fluid: expected \"saline\" or \"air\", got \"water\"");
  EXPECT_EQ(error_of(scenario_with_tissue(tissue, {{"syringe", {{"fluid", "saline"}, {"plunger_area_m2", 0}}}})),
            "/syringe/plunger_area_m2: must be in (0, 0.001] m^2, got 0");
  EXPECT_EQ(error_of(scenario_with_tissue(tissue, {{"syringe", {{"fluid", "saline"}, {"volume", 1}}}}))
                .rfind("/syringe/volume: unknown key", 0),
            0u);

  // In a parameter set: the set's file and the number's pointer.
  json set = test::read_json(test::asset("assets/tissues/epidural_space.json"));
  set["injection"]["opening_pressure_Pa"]["value"] = 2e6;
  const std::string set_path = test::own_file("epidural_space.json");
  std::ofstream(set_path) << set.dump(1);
  const std::string scenario =
      scenario_with_tissue({{"layers", {{{"name", "x"}, {"shape", slab(0.05, 0.01)}, {"parameters", set_path}}}}});
  try {
    load_scenario(scenario);
    ADD_FAILURE() << "loaded";
  } catch (const ScenarioError& e) {
    EXPECT_EQ(std::string(e.what()),
              set_path + ": /injection/opening_pressure_Pa/value: must be in [0, 1e+06] Pa, got 2e+06");
  }
}

TEST(TissueFiles, TheSingleSurfaceFormIsOneLayerWithEveryParameterZero) {
  const Scenario s = load_scenario(test::asset("assets/scenarios/nonholonomic_needle.json"));
  ASSERT_EQ(s.scene.tissue.layer_count(), 1);
  const LayerMechanics& m = s.scene.tissue.layer(0).mechanics;
  for (const auto& f : kMechanicsFields) EXPECT_EQ(m.*f.member, 0.0) << f.key;
  EXPECT_FALSE(m.rigid);
  // Same region as the closed loop's tissue: the thesis's sphere, r = 0.1 m at (0.4, 0, 0).
  for (const Vector3d& x :
       {Vector3d(0.4, 0, 0), Vector3d(0.4, 0, 0.099), Vector3d(0.4, 0, 0.101), Vector3d(0.2, 0, 0)}) {
    const Vector3d base = x - s.base_in_world;
    EXPECT_EQ(s.scene.tissue.layer_at(base) == 0, (x - Vector3d(0.4, 0, 0)).norm() < 0.1);
    EXPECT_NEAR(s.scene.tissue.distance(base), (x - Vector3d(0.4, 0, 0)).norm() - 0.1, 1e-15);
  }
}

TEST(TissueFiles, BadInlineLayersAreErrorsWithTheirPointer) {
  auto edited = [](const std::function<void(json&)>& edit) {
    json t = two_slabs();
    edit(t);
    return error_of(scenario_with_tissue(t));
  };
  EXPECT_EQ(edited([](json&) {}), "no error");
  EXPECT_EQ(edited([](json& t) { t["layers"][0]["puncture_force_N"] = -1.0; }),
            "/tissue/layers/0/puncture_force_N: must be >= 0, got -1.000000");
  EXPECT_EQ(edited([](json& t) { t["layers"][0]["stiffness_N_per_m"] = 0.0; }),
            "/tissue/layers/0/puncture_force_N: needs stiffness_N_per_m or stiffness2_N_per_m2 > 0 (a surface without "
            "stiffness never reaches it)");
  EXPECT_EQ(edited([](json& t) { t["layers"][1]["static_friction_N_per_m"] = 10.0; }),
            "/tissue/layers/1/static_friction_N_per_m: must be >= friction_N_per_m (the stick limit is at least the "
            "slip force)");
  EXPECT_EQ(edited([](json& t) { t["layers"][1]["shape"] = slab(0.048, 0.01); }),
            "/tissue/layers/1/shape: overlaps an earlier layer without lying inside it (layer 0, \"skin\")");
  EXPECT_EQ(edited([](json& t) { t["layers"][1]["name"] = "skin"; }),
            "/tissue/layers/1/name: \"skin\" names an earlier layer too");
  EXPECT_EQ(edited([](json& t) { t["layers"][0]["stiffnes_N_per_m"] = 1.0; }).substr(0, 48),
            "/tissue/layers/0/stiffnes_N_per_m: unknown key (");
  EXPECT_EQ(edited([](json& t) {
              t["layers"][0]["shape"] = {{"box", {{"min", {0, 0, 0}}, {"max", {1, 1, 0}}}}};
            }),
            "/tissue/layers/0/shape/box/max: must exceed min on every axis");
  EXPECT_EQ(edited([](json& t) {
              t["layers"][0]["shape"]["sphere"] = {{"centre", {0, 0, 0}}, {"radius", 1}};
            }),
            "/tissue/layers/0/shape: expected exactly one of \"sphere\", \"plane\", \"capsule\", \"slab\", \"box\", "
            "\"surface\"");
  EXPECT_EQ(
      edited([](json& t) {
        t["layers"][1] = {{"name", "bone"}, {"shape", slab(0.047, 0.01)}, {"rigid", true}, {"friction_N_per_m", 5}};
      }),
      "/tissue/layers/1/friction_N_per_m: a rigid layer takes no other parameter (it is the GPM contact of (3.15))");
  EXPECT_EQ(
      edited([](json& t) { t["layers"][0]["parameters"] = "../tissues/skin.json"; }),
      "/tissue/layers/0/stiffness_N_per_m: given beside \"parameters\": a layer's parameters come from the file or "
      "inline, not both");
  EXPECT_EQ(edited([](json& t) {
              t["stick"] = {{"band_mps", 0}};
            }),
            "/tissue/stick/band_mps: must be in (0, 0.1] m/s, got 0");
}

TEST(TissueFiles, NestedSpheresLoadAndCrossingOnesDoNot) {
  auto sphere = [](double x, double r) { return json{{"sphere", {{"centre", {x, 0.0, 0.0}}, {"radius", r}}}}; };
  auto two = [&](const json& inner) {
    return json{{"layers", {{{"name", "outer"}, {"shape", sphere(0.4, 0.1)}}, {{"name", "inner"}, {"shape", inner}}}}};
  };
  EXPECT_EQ(error_of(scenario_with_tissue(two(sphere(0.4, 0.05)))), "no error");
  EXPECT_EQ(error_of(scenario_with_tissue(two(sphere(0.48, 0.05)))),
            "/tissue/layers/1/shape: overlaps an earlier layer without lying inside it (layer 0, \"outer\")");
  EXPECT_EQ(
      error_of(scenario_with_tissue(two(sphere(0.4, 0.2)))),
      "/tissue/layers/1/shape: holds an earlier layer wholly inside it (list inner layers after outer ones) (layer 0, "
      "\"outer\")");
}

TEST(TissueFiles, SlabsAndBoxesMayTouchButNotCross) {
  const LayerShape top = LayerShape::slab(Vector3d(0, 0, 0), Vector3d::UnitZ(), 0.01);
  const LayerShape below = LayerShape::slab(Vector3d(0, 0, -0.01), Vector3d::UnitZ(), 0.02);
  const LayerShape tilted = LayerShape::slab(Vector3d(0, 0, -0.01), Vector3d(0.1, 0, 1), 0.02);
  const LayerShape flipped = LayerShape::slab(Vector3d(0, 0, -0.03), -Vector3d::UnitZ(), 0.02);  // the same as `below`
  const std::vector<LayerShape> stack{top, below};
  EXPECT_FALSE(find_layer_conflict(stack));
  const std::vector<LayerShape> crossing{top, tilted};
  ASSERT_TRUE(find_layer_conflict(crossing));
  EXPECT_EQ(find_layer_conflict(crossing)->kind, LayerConflict::Kind::PartialOverlap);
  const std::vector<LayerShape> same{below, flipped};
  EXPECT_EQ(find_layer_conflict(same)->kind,
            LayerConflict::Kind::HiddenInside);  // equal: the first would never hold the tip
  const LayerShape box_a = LayerShape::box(Vector3d(0, 0, 0), Vector3d(0.1, 0.1, 0.01));
  const LayerShape box_b = LayerShape::box(Vector3d(0, 0, -0.02), Vector3d(0.1, 0.1, 0.0));
  const LayerShape box_c = LayerShape::box(Vector3d(0.05, 0.05, 0.0095), Vector3d(0.2, 0.2, 0.02));  // 0.5 mm into a
  const std::vector<LayerShape> touching{box_a, box_b}, overlapping{box_a, box_c}, boxed_slab{top, box_c};
  EXPECT_FALSE(find_layer_conflict(touching));
  EXPECT_EQ(find_layer_conflict(overlapping)->kind, LayerConflict::Kind::PartialOverlap);
  EXPECT_EQ(find_layer_conflict(boxed_slab)->kind, LayerConflict::Kind::PartialOverlap);
}

TEST(TissueFiles, BadParameterSetsAreErrorsInTheirOwnFile) {
  const json skin = test::read_json(test::asset("assets/tissues/skin.json"));
  auto error_in_set = [&](const std::function<void(json&)>& edit) {
    json set = skin;
    edit(set);
    const std::string path = test::own_file("parameters.json");
    std::ofstream(path) << set.dump(1);
    const json tissue = {{"layers", {{{"name", "x"}, {"shape", slab(0.05, 0.01)}, {"parameters", path}}}}};
    const std::string error = error_of(scenario_with_tissue(tissue));
    return error.rfind(path + ": ", 0) == 0 ? error.substr(path.size() + 2) : "elsewhere: " + error;
  };
  EXPECT_EQ(error_in_set([](json& s) { s["puncture_force_N"] = 1.2; }),
            "/puncture_force_N: expected {\"value\": ..., \"source\": \"...\"}: every number in a parameter set "
            "carries its source");
  EXPECT_EQ(error_in_set([](json& s) { s["cutting_force_N"]["value"] = -0.4; }),
            "/cutting_force_N/value: must be >= 0, got -0.400000");
  EXPECT_EQ(error_in_set([](json& s) { s["puncture_force_N"]["source"] = "smith2020: table 2"; }),
            "/puncture_force_N/source: cites \"smith2020\", which is not in /references");
  EXPECT_EQ(error_in_set([](json& s) { s["puncture_force_N"]["source"] = "measured"; }),
            "/puncture_force_N/source: expected \"design value: why\" or \"<reference>: where in it\"");
  EXPECT_EQ(error_in_set([](json& s) { s["references"]["extra2000"] = "A. Nobody, Unused, 2000"; }),
            "/references/extra2000: not cited by any parameter's source");
  EXPECT_EQ(error_in_set([](json& s) { s.erase("friction_N_per_m"); }), "/friction_N_per_m: missing");
  EXPECT_EQ(
      error_in_set([](json& s) {
        s["stiffness_N_per_m"]["value"] = 0.0;
        s["stiffness2_N_per_m2"]["value"] = 0.0;
      }),
      "/puncture_force_N/value: needs stiffness_N_per_m or stiffness2_N_per_m2 > 0 (a surface without stiffness never "
      "reaches it)");
  EXPECT_EQ(error_in_set([](json& s) { s["colour"] = "pink"; }).substr(0, 20), "/colour: unknown key");
  EXPECT_EQ(error_in_set([](json& s) { s["ultrasound"]["echogenicity"]["value"] = 1.5; }),
            "/ultrasound/echogenicity/value: must be in [0, 1], got 1.5");
  EXPECT_EQ(error_in_set([](json& s) { s["ultrasound"]["impedance_MRayl"] = 1.99; }),
            "/ultrasound/impedance_MRayl: expected {\"value\": ..., \"source\": \"...\"}: every number in a parameter "
            "set carries its source");
  EXPECT_EQ(error_in_set([](json& s) { s["ultrasound"].erase("scatterer_density"); }),
            "/ultrasound/scatterer_density: missing");
  EXPECT_EQ(error_in_set([](json& s) { s["ultrasound"]["attenuation_dB_per_cm_MHz"]["source"] = "duck1990: p. 99"; }),
            "/ultrasound/attenuation_dB_per_cm_MHz/source: cites \"duck1990\", which is not in /references");
}

TEST(TissueFiles, UltrasoundParametersInlineOrFromTheSetNotBoth) {
  json t = two_slabs();
  t["layers"][1]["ultrasound"] = {{"impedance_MRayl", 1.39},
                                  {"attenuation_dB_per_cm_MHz", 0.63},
                                  {"echogenicity", 0.25},
                                  {"scatterer_density", 0.5}};
  const Scenario s = load_scenario(scenario_with_tissue(t));
  EXPECT_FALSE(s.scene.tissue.layer(0).acoustics.has_value());  // the image takes a generic soft tissue
  ASSERT_TRUE(s.scene.tissue.layer(1).acoustics.has_value());
  EXPECT_EQ(s.scene.tissue.layer(1).acoustics->scatterer_density, 0.5);

  t["layers"][1]["ultrasound"]["scatterer_density"] = 0.0;
  EXPECT_EQ(error_of(scenario_with_tissue(t)), "/tissue/layers/1/ultrasound/scatterer_density: must be in (0, 1]");
  t["layers"][1]["ultrasound"].erase("scatterer_density");
  t["layers"][1]["parameters"] = test::asset("assets/tissues/subcutaneous_fat.json");
  t["layers"][1].erase("friction_N_per_m");
  t["layers"][1].erase("static_friction_N_per_m");
  EXPECT_EQ(
      error_of(scenario_with_tissue(t)),
      "/tissue/layers/1/ultrasound: given beside \"parameters\": a layer's parameters come from the file or inline, "
      "not both");
}

}  // namespace
}  // namespace needle::haptics

namespace needle::haptics {
namespace {

TEST(TissueTent, TheTentsDepthIsTheRootOfTheSurfaceForceAtThePunctureForce) {
  LayerMechanics linear{.stiffness_N_per_m = 200, .puncture_force_N = 1.0};
  EXPECT_DOUBLE_EQ(tent_depth_m(linear), 0.005);
  LayerMechanics quadratic{.stiffness_N_per_m = 100, .stiffness2_N_per_m2 = 20000, .puncture_force_N = 2.0};
  const double d = tent_depth_m(quadratic);
  EXPECT_NEAR(100 * d + 20000 * d * d, 2.0, 1e-12);
  EXPECT_EQ(tent_depth_m(LayerMechanics{.cutting_force_N = 0.1}), 0.0);  // no surface: entered when reached
  EXPECT_EQ(tent_depth_m(LayerMechanics{.rigid = true}), 0.0);
}

// In every shipped layered scenario, along the line its task or profile inserts on (docs/TISSUE.md,
// "Profiles"), each surface gives way before its tent reaches the next structure (the next surface or
// bone), and a layer with a cutting force gives way within its own thickness, so that it is cut
// after its pop. The dura is the exception a source makes: it tents 2-6 mm (Zarzur and Gonçalves
// 1992) in a 0.5 mm membrane.
TEST(TissueTent, EveryShippedLayerGivesWayBeforeItsTentReachesTheNextStructure) {
  struct Line {
    const char* scenario;
    Vector3d from, dir;
  };
  const Line lines[] = {{"tissue_block_layers", {0.33, 0, 0.075}, {0, 0, -1}},
                        {"lumbar_epidural", {0.33, 0, 0.075}, {0, 0, -1}},
                        {"epidural", {0.33, 0, 0.075}, {0, 0, -1}},
                        {"liver_biopsy", {0.32575, 0, 0.07425}, Vector3d(1, 0, -1).normalized()}};
  for (const Line& line : lines) {
    const Scenario s = load_scenario(test::asset(std::string("assets/scenarios/") + line.scenario + ".json"));
    const TissueModel& tissue = s.scene.tissue;
    const std::vector<LayerBoundary> b = layer_boundaries(tissue, line.from, line.dir, 0.15);
    auto structure = [&](int layer) {
      return layer >= 0 && (tissue.layer(layer).mechanics.rigid || tent_depth_m(tissue.layer(layer).mechanics) > 0.0);
    };
    for (size_t k = 0; k < b.size(); ++k) {
      if (b[k].layer < 0) continue;
      const LayerMechanics& m = tissue.layer(b[k].layer).mechanics;
      const double tent = tent_depth_m(m);
      if (tent == 0.0) continue;
      const std::string name = std::string(line.scenario) + ": " + tissue.layer(b[k].layer).name;
      double next = std::numeric_limits<double>::infinity();
      for (size_t j = k + 1; j < b.size(); ++j)
        if (structure(b[j].layer)) {
          next = b[j].depth_m - b[k].depth_m;
          break;
        }
      EXPECT_LT(tent, next) << name << ": its tent reaches the next structure";
      const double thickness =
          k + 1 < b.size() ? b[k + 1].depth_m - b[k].depth_m : std::numeric_limits<double>::infinity();
      if (m.cutting_force_N > 0.0 && tissue.layer(b[k].layer).name != "dura")
        EXPECT_LT(tent, thickness) << name
                                   << ": it gives way only past its own far side, so its cutting force never acts";
    }
  }
}

}  // namespace
}  // namespace needle::haptics
