// `needle-sim bench insertion`: the JSON keys, the run through the shipped tissue block
// against the skin parameter set's closed form, the plot, and usage errors before any run.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>

#include "cli_process.hpp"
#include "engine/rgba_image.hpp"

namespace needle::test {
namespace {

nlohmann::json read_json(const std::filesystem::path& path) { return nlohmann::json::parse(std::ifstream(path)); }

TEST(CliBenchInsertion, JsonCarriesTheContractKeysAndThePlotIsWritten) {
  const auto dir = test_output_dir("cli_bench_insertion");
  const auto json_path = dir / "block.json", plot_path = dir / "block.png";
  // 5 mm above the tissue block's skin (top at z = 0.07 m), straight down, 6 cm: the bone plate at
  // z = 0.03 m stops the drive 45 mm in.
  const ProcessResult r = run_needle_sim(
      "bench insertion --scenario " + quoted(source_dir() / "assets/scenarios/tissue_block_layers.json") +
      " --from 0.33,0,0.075 --dir 0,0,-1 --depth 0.06 --speed 0.01 --hold 0.2 --json " + quoted(json_path) +
      " --plot " + quoted(plot_path));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("peak_force_N"), std::string::npos) << r.output;  // the table
  const nlohmann::json run = read_json(json_path);
  for (const char* key : {"samples", "punctures", "tissue_work_J", "tick_us_median"})
    ASSERT_TRUE(run.contains(key)) << key;
  ASSERT_GT(run["samples"].size(), 100u);
  for (const char* key : {"t", "depth_m", "axial_force_N", "layer"})
    EXPECT_TRUE(run["samples"][0].contains(key)) << key;
  EXPECT_EQ(run["samples"][0]["layer"], "");
  EXPECT_GT(run["tissue_work_J"].get<double>(), 0.0);
  EXPECT_GT(run["tick_us_median"].get<double>(), 0.0);
  EXPECT_EQ(run["hard_stop"]["layer"], "bone");
  EXPECT_NEAR(run["hard_stop"]["depth_m"].get<double>(), 0.045, 1e-9);

  // Skin then muscle fascia (fat has no surface); the skin gives way where its parameter set's
  // k1 d + k2 d^2 reaches the puncture force, 5 mm below the start.
  const nlohmann::json& punctures = run["punctures"];
  ASSERT_EQ(punctures.size(), 2u);
  for (const char* key : {"layer", "depth_m", "peak_force_N"}) EXPECT_TRUE(punctures[0].contains(key)) << key;
  EXPECT_EQ(punctures[0]["layer"], "skin");
  EXPECT_EQ(punctures[1]["layer"], "muscle");
  const nlohmann::json skin = read_json(source_dir() / "assets/tissues/skin.json");
  const double k1 = skin["stiffness_N_per_m"]["value"], k2 = skin["stiffness2_N_per_m2"]["value"],
               fp = skin["puncture_force_N"]["value"];
  const double deflection = (-k1 + std::sqrt(k1 * k1 + 4 * k2 * fp)) / (2 * k2);
  // The surface gives way on the first tick its force reaches F_p: up to one tick's travel (0.01 m/s
  // at the scenario's 2 ms) past the root, and as much more force as the surface's slope then makes.
  const double tick_travel = 0.01 * 0.002, slope = k1 + 2 * k2 * deflection;
  EXPECT_GE(punctures[0]["depth_m"].get<double>(), 0.005 + deflection - 1e-9);
  EXPECT_LE(punctures[0]["depth_m"].get<double>(), 0.005 + deflection + tick_travel + 1e-9);
  EXPECT_GE(punctures[0]["peak_force_N"].get<double>(), fp);
  EXPECT_LE(punctures[0]["peak_force_N"].get<double>(), fp + slope * tick_travel + 1e-9);

  const engine::RgbaImage plot = engine::read_png(plot_path);
  EXPECT_EQ(plot.width, 1200u);
  EXPECT_EQ(plot.height, 700u);
}

// With the syringe (docs/TISSUE.md, "The syringe"): the keys on each sample and the losses
// of resistance, each where the fluid could first go into its layer (within a tick's travel), the one in the epidural
// space after the held pressure of the 11 N thumb, F / A, and a lower one after it. Bad syringe flags are usage errors
// (below).
TEST(CliBenchInsertion, WithTheSyringeEachSampleHasThePlungerAndTheLossesAreListed) {
  const auto dir = test_output_dir("cli_bench_insertion");
  for (const char* fluid : {"saline", "air"}) {
    const auto json_path = dir / (std::string("lumbar_") + fluid + ".json");
    const ProcessResult r =
        run_needle_sim("bench insertion --scenario " + quoted(source_dir() / "assets/scenarios/lumbar_epidural.json") +
                       " --from 0.33,0,0.075 --dir 0,0,-1 --depth 0.065 --speed 0.005 --syringe " + fluid +
                       " --plunger-force 11 --json " + quoted(json_path));
    ASSERT_EQ(r.exit_code, 0) << r.output;
    EXPECT_NE(r.output.find("losses of resistance"), std::string::npos) << r.output;
    const nlohmann::json run = read_json(json_path);
    for (const nlohmann::json& s : run["samples"]) {
      ASSERT_TRUE(s.contains("plunger_pressure_Pa") && s.contains("plunger_travel_m"));
      EXPECT_GE(s["plunger_travel_m"].get<double>(), 0.0);
    }
    ASSERT_TRUE(run.contains("loss_of_resistance")) << fluid;
    const nlohmann::json* epidural = nullptr;
    for (const nlohmann::json& l : run["loss_of_resistance"]) {
      for (const char* key : {"depth_m", "layer", "pressure_before_Pa", "pressure_after_Pa"})
        ASSERT_TRUE(l.contains(key)) << key;
      if (l["layer"] == "epidural space" && !epidural) epidural = &l;
      // Each loss within a tick's travel (10 um) after where the fluid could first go there: the
      // boundary of the layer it went into, or the puncture of the membrane in front of it (the
      // dura's tent carries the tip past the cerebrospinal fluid's boundary at rest).
      const double depth = l["depth_m"].get<double>();
      const auto just_after = [&](double at) { return depth >= at - 1e-9 && depth <= at + 1e-5 + 1e-9; };
      bool where = false;
      for (const nlohmann::json& b : run["boundaries"])
        where = where || (b["layer"] == l["layer"] && just_after(b["depth_m"]));
      for (const nlohmann::json& p : run["punctures"]) where = where || just_after(p["depth_m"]);
      EXPECT_TRUE(where) << fluid << " " << l.dump();
    }
    ASSERT_NE(epidural, nullptr) << fluid;
    const double held = 11.0 / 1.77e-4;
    EXPECT_NEAR((*epidural)["pressure_before_Pa"].get<double>(), held, 1e-6 * held) << fluid;
    EXPECT_LT((*epidural)["pressure_after_Pa"].get<double>(), held) << fluid;
  }
}

TEST(CliBenchInsertion, BadArgumentsAndMissingOutputFoldersAreUsageErrorsBeforeTheRun) {
  const std::string scenario = quoted(source_dir() / "assets/scenarios/lumbar_epidural.json");
  const std::string line = "bench insertion --scenario " + scenario + " --from 0.33,0,0.075 --dir 0,0,-1 ";
  const ProcessResult missing = run_needle_sim(line + "--depth 0.05 --speed 0.005 --json /nonexistent/folder/out.json");
  EXPECT_EQ(missing.exit_code, 2);
  EXPECT_NE(missing.output.find("--json: folder /nonexistent/folder does not exist"), std::string::npos)
      << missing.output;
  EXPECT_EQ(missing.output.find("punctures"), std::string::npos) << missing.output;  // nothing ran
  EXPECT_EQ(run_needle_sim(line + "--depth 0.05 --speed 0.005 --plot /nonexistent/plot.png").exit_code, 2);
  EXPECT_EQ(run_needle_sim(line + "--depth 0.05 --speed 0").exit_code, 2);
  EXPECT_EQ(run_needle_sim(line + "--depth -1 --speed 0.005").exit_code, 2);
  EXPECT_EQ(run_needle_sim(line + "--depth 0.05 --speed 0.005 --hold -1").exit_code, 2);
  EXPECT_EQ(run_needle_sim(line + "--depth 0.05 --speed 0.005 --syringe water --plunger-force 11").exit_code, 2);
  EXPECT_EQ(run_needle_sim(line + "--depth 0.05 --speed 0.005 --syringe saline").exit_code, 2);    // no force
  EXPECT_EQ(run_needle_sim(line + "--depth 0.05 --speed 0.005 --plunger-force 11").exit_code, 2);  // no syringe
  EXPECT_EQ(run_needle_sim(line + "--depth 0.05 --speed 0.005 --syringe air --plunger-force 1e6").exit_code, 2);
  EXPECT_EQ(run_needle_sim("bench insertion --scenario " + scenario +
                           " --from 0.33,0 --dir 0,0,-1 --depth 0.05 --speed 0.005")
                .exit_code,
            2);
}

}  // namespace
}  // namespace needle::test
