// `needle-sim patient` and the patient scenario in `bench insertion`: the report's contract keys,
// the fields and meshes written (each read back), the midline needle through the patient's layers
// in order and the needle 20° off the midline stopped on bone. CliPatient generates patients: it is
// in SANITIZE_SKIP (tests/README.md).
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>

#include "cli_process.hpp"
#include "engine/gltf_loader.hpp"
#include "haptics/anatomy/sdf_file.hpp"

namespace needle::test {
namespace {

nlohmann::json read_json(const std::filesystem::path& path) { return nlohmann::json::parse(std::ifstream(path)); }

// The BMI 22 patient written by `patient`, once for the tests below.
const std::filesystem::path& bmi22_dir() {
  static const std::filesystem::path dir = [] {
    const auto out = test_output_dir("cli_patient") / "bmi22";
    const ProcessResult r = run_needle_sim("patient --patient " + quoted(source_dir() / "assets/patients/bmi22.json") +
                                           " --out " + quoted(out));
    EXPECT_EQ(r.exit_code, 0) << r.output;
    return out;
  }();
  return dir;
}

TEST(CliPatient, TheReportCarriesTheContractKeysAndTheFilesReadBack) {
  const nlohmann::json report = read_json(bmi22_dir() / "patient.json");
  ASSERT_EQ(report["vertebrae"].size(), 5u);
  for (const nlohmann::json& v : report["vertebrae"])
    for (const char* key : {"level", "body_height_m", "spinous_process_length_m", "interlaminar_gap_m"})
      EXPECT_TRUE(v.contains(key)) << key;
  EXPECT_EQ(report["vertebrae"][2]["level"], "L3");
  for (const char* interspace : {"L1-L2", "L2-L3", "L3-L4", "L4-L5", "L5-S1"})
    for (const char* key : {"skin_to_epidural_m", "supraspinous_to_epidural_m", "skin_to_dura_m"})
      EXPECT_TRUE(report[interspace].contains(key)) << interspace << " " << key;
  const nlohmann::json& l34 = report["L3-L4"];
  EXPECT_NEAR(l34["skin_to_epidural_m"].get<double>(), 0.0473,
              0.0005);  // docs/PATIENTS.md: the depth equation's 47.3 mm
  EXPECT_GT(l34["skin_to_dura_m"].get<double>(), l34["skin_to_epidural_m"].get<double>());
  EXPECT_LT(l34["supraspinous_to_epidural_m"].get<double>(), l34["skin_to_epidural_m"].get<double>());
  ASSERT_EQ(report["layers"].size(), 12u);
  for (const nlohmann::json& layer : report["layers"]) {
    SCOPED_TRACE(layer["name"].get<std::string>());
    const haptics::SdfGrid grid =
        haptics::anatomy::read_sdf_file((bmi22_dir() / layer["field"].get<std::string>()).string());
    EXPECT_EQ(grid.spacing(), 1e-3);
    const engine::Model mesh = engine::load_gltf(bmi22_dir() / layer["mesh"].get<std::string>());
    ASSERT_EQ(mesh.primitives.size(), 1u);
    EXPECT_GT(mesh.primitives[0].indices.size(), 100u);
    // The mesh lies in its field's box.
    for (int a = 0; a < 3; ++a) {
      EXPECT_GE(mesh.world_bounds.min[a], grid.origin()[a] - 1e-3);
      EXPECT_LE(mesh.world_bounds.max[a], grid.upper()[a] + 1e-3);
    }
  }
}

// Along the L3–L4 approach of the patient scenario (its skin entry at (0.33, 0, 0.07) m), from 5 mm
// above the skin.
std::string approach_flags(const nlohmann::json& report, double turn_deg) {
  const nlohmann::json& l34 = report["L3-L4"];
  double d[3], n = 0.0;
  for (int a = 0; a < 3; ++a)
    n += std::pow(d[a] = l34["window_m"][a].get<double>() - l34["entry_m"][a].get<double>(), 2);
  for (double& x : d) x /= std::sqrt(n);
  const double t = turn_deg * M_PI / 180.0;  // about the spine's axis (y), towards the patient's right
  const double dx = d[0] * std::cos(t) + d[2] * std::sin(t), dz = -d[0] * std::sin(t) + d[2] * std::cos(t);
  char flags[256];
  std::snprintf(flags, sizeof flags, " --from %.6f,%.6f,%.6f --dir %.6f,%.6f,%.6f", 0.33 - 0.005 * dx, -0.005 * d[1],
                0.07 - 0.005 * dz, dx, d[1], dz);
  return flags;
}

TEST(CliPatient, BenchInsertionOnThePatientMeetsTheLayersInOrderAndBoneOffTheMidline) {
  const nlohmann::json report = read_json(bmi22_dir() / "patient.json");
  const auto dir = test_output_dir("cli_patient");
  const std::string scenario = " --scenario " + quoted(source_dir() / "assets/scenarios/epidural_patient.json");
  const ProcessResult midline = run_needle_sim("bench insertion" + scenario + approach_flags(report, 0.0) +
                                               " --depth 0.06 --speed 0.005 --json " + quoted(dir / "midline.json"));
  ASSERT_EQ(midline.exit_code, 0) << midline.output;
  const nlohmann::json run = read_json(dir / "midline.json");
  std::vector<std::string> met;
  for (const nlohmann::json& b : run["boundaries"]) met.push_back(b["layer"]);
  ASSERT_GE(met.size(), 6u);
  EXPECT_EQ(std::vector<std::string>(met.begin(), met.begin() + 6),
            (std::vector<std::string>{"skin", "subcutaneous fat", "supraspinous ligament", "interspinous ligament",
                                      "ligamentum flavum", "epidural space"}));
  EXPECT_TRUE(run["hard_stop"].is_null());
  std::vector<std::string> punctured;
  for (const nlohmann::json& p : run["punctures"]) punctured.push_back(p["layer"]);
  EXPECT_NE(std::find(punctured.begin(), punctured.end(), "ligamentum flavum"), punctured.end());

  const ProcessResult off = run_needle_sim("bench insertion" + scenario + approach_flags(report, 20.0) +
                                           " --depth 0.06 --speed 0.005 --json " + quoted(dir / "off_midline.json"));
  ASSERT_EQ(off.exit_code, 0) << off.output;
  const nlohmann::json stopped = read_json(dir / "off_midline.json");
  ASSERT_TRUE(stopped["hard_stop"].is_object());
  EXPECT_EQ(stopped["hard_stop"]["layer"], "bone");
  for (const nlohmann::json& p : stopped["punctures"]) EXPECT_NE(p["layer"], "ligamentum flavum");
}

TEST(CliPatient, ABadPatientFileIsOneLineNamingTheKey) {
  const auto dir = test_output_dir("cli_patient");
  const auto bad = dir / "tall.json";
  nlohmann::json p = read_json(source_dir() / "assets/patients/bmi22.json");
  p["height_m"] = 2.5;
  std::ofstream(bad) << p.dump();
  const ProcessResult r = run_needle_sim("patient --patient " + quoted(bad) + " --out " + quoted(dir / "tall"));
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.output.find(bad.string() + ": /height_m: must be in [1.45, 2.05] m, got 2.5"), std::string::npos)
      << r.output;
  EXPECT_FALSE(std::filesystem::exists(dir / "tall" / "patient.json"));
}

}  // namespace
}  // namespace needle::test
