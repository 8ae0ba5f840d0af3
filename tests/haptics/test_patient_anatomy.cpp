// The generated lumbar patient (haptics/anatomy/): its dimensions against the closed forms of
// the sources recomputed here from their numbers, the skin-to-epidural depth at L3–L4 against the
// clinical prediction and ranges, the layers a midline needle meets in order, bone off the midline,
// flexion opening the interlaminar windows, and the patient file's errors. PatientGeneration's
// tests generate patients (about 0.6 s each here, minutes sanitized: SANITIZE_SKIP).
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

#include "haptics/anatomy/morphometry.hpp"
#include "haptics/anatomy/patient.hpp"
#include "haptics/sim/scenario.hpp"
#include "haptics/tissue/kinematic_insertion.hpp"
#include "robot_fixtures.hpp"
#include "scenario_files.hpp"

namespace needle::haptics::anatomy {
namespace {

using Eigen::Vector3d;
constexpr int kL3L4 = 2;

PatientParams shipped(const std::string& name) {
  return load_patient(test::asset("assets/patients/" + name + ".json"));
}

// Where a line from `start` along `dir` enters each layer (the geometry alone), with its name.
struct Crossing {
  std::string layer;
  double depth_m;
};
std::vector<Crossing> crossings(const Patient& p, const TissueModel& m, const Vector3d& start, const Vector3d& dir,
                                double length) {
  std::vector<Crossing> out;
  for (const LayerBoundary& b : layer_boundaries(m, start, dir, length))
    out.push_back({b.layer >= 0 ? p.layers[size_t(b.layer)].name : "", b.depth_m});
  return out;
}

double depth_of(const std::vector<Crossing>& c, const std::string& layer) {
  for (const Crossing& x : c)
    if (x.layer == layer) return x.depth_m;
  return -1.0;
}

// [Cook2021] Table 6 and [Guj2012], [Vallejo2012] (haptics/anatomy/morphometry.cpp), typed again
// from the sources here: the generator must give exactly these for a patient of seed 0.
TEST(PatientAnatomy, DimensionsAreTheSourcesClosedForms) {
  for (const char* name : {"bmi22", "bmi30", "bmi40"}) {
    SCOPED_TRACE(name);
    const PatientParams p = shipped(name);
    const bool female = p.sex == Sex::Female;
    const double s = p.height_m / (female ? 1.63 : 1.77), age = p.age_years - 45.0;
    const PatientDimensions d = patient_dimensions(p);
    const VertebraDimensions& l5 = d.vertebrae[4];
    EXPECT_NEAR(l5.body_height_m, (female ? 25.5 : 26.8) * s * 1e-3, 1e-12);
    EXPECT_NEAR(l5.body_depth_m, ((female ? 33.3 : 37.1) * s + 0.084 * age) * 1e-3, 1e-12);
    EXPECT_NEAR(l5.canal_depth_m, (female ? 15.1 : 15.9) * s * 1e-3, 1e-12);
    EXPECT_NEAR(l5.canal_width_m, ((female ? 27.6 : 28.5) * s + 0.033 * age) * 1e-3, 1e-12);
    EXPECT_NEAR(l5.pedicle_width_m, ((female ? 15.1 : 16.6) * s + 0.033 * age) * 1e-3, 1e-12);
    EXPECT_NEAR(d.vertebrae[0].body_width_m, (female ? 31.6 : 36.3) * s * 1e-3, 1e-12);
    EXPECT_NEAR(l5.body_width_m, (female ? 42.8 : 46.0) * s * 1e-3, 1e-12);
    // The canal's length is the same at every level; its width grows as the interpedicular distance.
    const double ip1 = female ? 21.3 : 22.6, ip5 = female ? 26.4 : 27.0;
    EXPECT_NEAR(d.vertebrae[2].canal_depth_m, l5.canal_depth_m, 1e-15);
    EXPECT_NEAR(d.vertebrae[0].canal_width_m, ((female ? 27.6 : 28.5) * ip1 / ip5 * s + 0.033 * age) * 1e-3, 1e-12);
    const double inches = p.height_m / 0.0254, pounds = p.weight_kg / 0.45359237;
    EXPECT_NEAR(d.skin_to_epidural_l3_l4_m, (6.63 - 0.07 * inches + 0.02 * pounds) / 100.0, 1e-12);
    for (int level = 0; level < kLumbarLevels; ++level)
      EXPECT_EQ(d.vertebrae[size_t(level)].spinous_process_length_m,
                vertebra_closed_form(p, level).spinous_process_length_m);
  }
}

// Generated and measured on the grids, along the midline approach: the depth the prediction equation
// gives (to the grids' sampling, 0.5 mm), and within what the clinical studies report for the BMI
// (RAPM 2019;44 Suppl 1:A192: 4 to 6 cm in about 80 % of people, 5.3 ± 1 cm in 100 women of mean BMI
// about 30, up to 8 cm in the obese; McLendon et al., SOAP 2014: 6.2 ± 1.4 cm at a mean BMI of 32.4).
TEST(PatientGeneration, SkinToEpiduralAtL3L4IsTheClinicalDepth) {
  struct Case {
    const char* name;
    double lo_m, hi_m;
  };
  for (const Case& c : {Case{"bmi22", 0.040, 0.060}, Case{"bmi30", 0.043, 0.063}, Case{"bmi40", 0.048, 0.080}}) {
    SCOPED_TRACE(c.name);
    const PatientParams params = shipped(c.name);
    const Patient p = generate_patient(params);
    const TissueModel m = geometry_model(p);
    const Approach& a = p.approaches[kL3L4];
    const std::vector<Crossing> path = crossings(p, m, a.entry + 0.005 * -a.direction(), a.direction(), 0.15);
    const double skin = depth_of(path, "skin"), epidural = depth_of(path, "epidural space");
    ASSERT_GE(skin, 0.0);
    ASSERT_GT(epidural, skin);
    EXPECT_NEAR(epidural - skin, epidural_depth_equation_m(params), 0.0005);
    EXPECT_GT(epidural - skin, c.lo_m);
    EXPECT_LT(epidural - skin, c.hi_m);
  }
}

// Straight down the midline approach at L3–L4: skin, subcutaneous fat, supraspinous, interspinous,
// flavum, epidural space, in that order, then the dura.
TEST(PatientGeneration, TheMidlineNeedleMeetsTheLayersInOrder) {
  for (const char* name : {"bmi22", "bmi30", "bmi40"}) {
    SCOPED_TRACE(name);
    const Patient p = generate_patient(shipped(name));
    const TissueModel m = geometry_model(p);
    const Approach& a = p.approaches[kL3L4];
    std::vector<std::string> met;
    for (const Crossing& c : crossings(p, m, a.entry - 0.005 * a.direction(), a.direction(), 0.12))
      if (met.empty() || met.back() != c.layer) met.push_back(c.layer);
    ASSERT_GE(met.size(), 7u);
    EXPECT_EQ(std::vector<std::string>(met.begin(), met.begin() + 7),
              (std::vector<std::string>{"skin", "subcutaneous fat", "supraspinous ligament", "interspinous ligament",
                                        "ligamentum flavum", "epidural space", "dura"}));
  }
}

// 20° off the midline from the same entry, turned towards the patient's right about the spine's
// axis: the needle meets bone (the lamina or the articular pillar that closes the window's side)
// before any epidural space. Not in the BMI 40 patient: there the epidural space is 68 mm deep and
// 20° carries the tip 25 mm off the midline at the canal's depth, past the facet joints.
TEST(PatientGeneration, TwentyDegreesOffTheMidlineTheNeedleMeetsALamina) {
  for (const char* name : {"bmi22", "bmi30"}) {
    SCOPED_TRACE(name);
    const Patient p = generate_patient(shipped(name));
    const TissueModel m = geometry_model(p);
    const Approach& a = p.approaches[kL3L4];
    const Vector3d dir = Eigen::AngleAxisd(20.0 * M_PI / 180.0, Vector3d::UnitY()) * a.direction();
    const std::vector<Crossing> path = crossings(p, m, a.entry - 0.002 * dir, dir, 0.15);
    const double bone = depth_of(path, "bone"), epidural = depth_of(path, "epidural space");
    ASSERT_GT(bone, 0.0);
    EXPECT_TRUE(epidural < 0.0 || epidural > bone);
    const std::optional<InsertionStop> stop = first_rigid_surface(m, a.entry - 0.002 * dir, dir, 0.15);
    ASSERT_TRUE(stop.has_value());
    EXPECT_EQ(p.layers[size_t(stop->layer)].name, "bone");
    EXPECT_NEAR(stop->depth_m, bone, 1e-4);
  }
}

// Flexion opens the windows: the same patient sitting flexed has wider interlaminar gaps than lying
// on the side, and every window is open.
TEST(PatientAnatomy, FlexionOpensTheInterlaminarWindows) {
  PatientParams sitting = shipped("bmi22");
  PatientParams lying = sitting;
  lying.posture = Posture::Lateral;
  const Spine a = build_spine(patient_dimensions(sitting)), b = build_spine(patient_dimensions(lying));
  for (int k = 0; k < 5; ++k) {
    EXPECT_GT(a.interspaces[size_t(k)].interlaminar_gap_m, b.interspaces[size_t(k)].interlaminar_gap_m + 0.001) << k;
    EXPECT_GT(b.interspaces[size_t(k)].interlaminar_gap_m, 0.005) << k;
  }
}

TEST(PatientGeneration, TheSameParametersGiveTheSameFieldsAndSeedsVary) {
  const PatientParams p = shipped("bmi30");
  const Patient a = generate_patient(p), b = generate_patient(p);
  ASSERT_EQ(a.layers.size(), b.layers.size());
  for (size_t i = 0; i < a.layers.size(); ++i)
    EXPECT_EQ(a.layers[i].shape.grid()->values(), b.layers[i].shape.grid()->values());
  PatientParams other = p;
  other.seed = 17;
  const PatientDimensions d0 = patient_dimensions(p), d17 = patient_dimensions(other);
  EXPECT_NE(d0.vertebrae[2].spinous_process_length_m, d17.vertebrae[2].spinous_process_length_m);
  EXPECT_NEAR(d17.vertebrae[2].spinous_process_length_m / d0.vertebrae[2].spinous_process_length_m, 1.0, 0.1);
  EXPECT_EQ(random_patient(5).height_m, random_patient(5).height_m);
  for (uint64_t seed = 1; seed < 50; ++seed) {
    const PatientParams r = random_patient(seed);
    EXPECT_TRUE(kRandomHeightRange.contains(r.height_m));
    EXPECT_TRUE(kBmiRange.contains(r.bmi()));
    EXPECT_NE(r.seed, 0u);
  }
}

// Every patient the ranges allow is a valid tissue (its layers disjoint or nested, docs/TISSUE.md):
// the tallest and the shortest at both ends of the BMI, and patients a random draw of the ranges
// gave whose sacrum and transverse processes reached the iliac crests (each crest is cut where
// the vertebrae are, as every other structure is cut from the bone).
TEST(PatientGeneration, PatientsAtTheRangesEdgesAreValidTissue) {
  struct Case {
    double height_m, weight_kg;
    Sex sex;
    double age_years;
    Posture posture;
    uint32_t seed;
  };
  for (const Case& c : {Case{2.05, 2.05 * 2.05 * 16.0, Sex::Male, 18, Posture::SittingFlexed, 0},
                        Case{2.05, 200.0, Sex::Female, 90, Posture::Lateral, 0},
                        Case{1.45, 1.45 * 1.45 * 16.0, Sex::Female, 90, Posture::Lateral, 0},
                        Case{1.45, 1.45 * 1.45 * 60.0, Sex::Male, 18, Posture::SittingFlexed, 0},
                        Case{1.888, 71.1, Sex::Female, 51, Posture::SittingFlexed, 3232122210u},
                        Case{2.029, 109.1, Sex::Female, 46, Posture::SittingFlexed, 1706456525u},
                        Case{1.855, 174.0, Sex::Male, 86, Posture::Lateral, 2287157766u}}) {
    const PatientParams p{c.height_m, c.weight_kg, c.sex, c.age_years, c.posture, c.seed};
    SCOPED_TRACE(patient_json(p).dump());
    const Patient patient = generate_patient(p);
    EXPECT_NO_THROW(geometry_model(patient));
  }
}

std::string patient_error(const nlohmann::json& j) {
  const std::string path = test::own_file("patient.json");
  std::ofstream(path) << j.dump();
  try {
    load_patient(path);
  } catch (const PatientError& e) {
    const std::string what = e.what();
    return what.rfind(path + ": ", 0) == 0 ? what.substr(path.size() + 2) : what;
  }
  return "no error";
}

TEST(PatientAnatomy, BadPatientFilesAreOneLineErrorsNamingTheKeyAndTheRange) {
  nlohmann::json good = test::read_json(test::asset("assets/patients/bmi22.json"));
  EXPECT_EQ(patient_error(good), "no error");
  auto with = [&](const char* key, nlohmann::json value) {
    nlohmann::json j = good;
    j[key] = value;
    return patient_error(j);
  };
  EXPECT_EQ(with("height_m", 3.0), "/height_m: must be in [1.45, 2.05] m, got 3");
  EXPECT_EQ(with("weight_kg", 1e300), "/weight_kg: must be in [40, 200] kg, got 1e+300");
  EXPECT_EQ(with("weight_kg", 190.0),
            "/weight_kg: gives a BMI of 69.7888 with height_m 1.65: the BMI must be in [16, 60] kg/m^2");
  EXPECT_EQ(with("sex", "other"), "/sex: expected \"female\" or \"male\", got \"other\"");
  EXPECT_EQ(with("posture", "prone"), "/posture: expected \"sitting_flexed\" or \"lateral\", got \"prone\"");
  EXPECT_EQ(with("age_years", 5), "/age_years: must be in [18, 90] years, got 5");
  EXPECT_EQ(with("seed", -1), "/seed: expected a whole number from 0 to 4294967295");
  EXPECT_EQ(with("colour", 1),
            "/colour: unknown key (allowed: name, description, height_m, weight_kg, sex, age_years, posture, seed)");
  nlohmann::json missing = good;
  missing.erase("sex");
  EXPECT_EQ(patient_error(missing), "/sex: missing");
  // Given twice, a reader would keep one of the two seeds: the patient would depend on the reader.
  const std::string path = test::own_file("patient_twice.json");
  std::string text = good.dump();
  std::ofstream(path) << text.insert(text.size() - 1, ",\"seed\":7");
  try {
    load_patient(path);
    ADD_FAILURE() << "a seed given twice was read";
  } catch (const PatientError& e) {
    EXPECT_EQ(std::string(e.what()), path + ": /seed: the key is given twice in its object");
  }
}

// A scenario's patient tissue: the patient's errors name the scenario and the pointer into it.
TEST(PatientAnatomy, AScenariosPatientIsReadStrictly) {
  nlohmann::json s = test::read_json(test::asset("assets/scenarios/epidural_patient.json"));
  s["master_urdf"] = test::asset("assets/robots/master_omni.urdf");
  s["virtual_urdf"] = test::asset("assets/robots/virtual_needle_robot.urdf");
  const auto error = [&](const nlohmann::json& tissue) -> std::string {
    nlohmann::json copy = s;
    copy["tissue"] = tissue;
    const std::string path = test::own_file("scenario.json");
    std::ofstream(path) << copy.dump();
    try {
      load_scenario(path);
    } catch (const ScenarioError& e) {
      return std::string(e.what()).substr(path.size() + 2);
    }
    return "no error";
  };
  nlohmann::json inline_patient = test::read_json(test::asset("assets/patients/bmi22.json"));
  inline_patient["height_m"] = 3.0;
  const std::string tissues = test::asset("assets/tissues");
  EXPECT_EQ(error({{"patient", inline_patient}, {"entry", {0.33, 0, 0.07}}, {"tissues", tissues}}),
            "/tissue/patient/height_m: must be in [1.45, 2.05] m, got 3");
  EXPECT_EQ(error({{"patient", "nowhere.json"}, {"entry", {0.33, 0, 0.07}}, {"tissues", tissues}})
                .rfind("/tissue/patient: file not found", 0),
            0u);
  EXPECT_EQ(error({{"patient", inline_patient}, {"tissues", tissues}}),
            "/tissue/patient/height_m: must be in [1.45, 2.05] m, got 3");
  inline_patient["height_m"] = 1.65;
  EXPECT_EQ(error({{"patient", inline_patient}, {"tissues", tissues}}), "/tissue/entry: missing");
  EXPECT_EQ(error({{"patient", inline_patient}, {"entry", {0.33, 0, 1e9}}, {"tissues", tissues}}),
            "/tissue/entry/2: must be in [-10, 10] m, got 1e+09");
  EXPECT_EQ(error({{"patient", inline_patient}, {"entry", {0.33, 0, 0.07}}, {"tissues", "/nonexistent"}}),
            "/tissue/tissues: folder not found: /nonexistent");
  EXPECT_EQ(error({{"patient", inline_patient}, {"entry", {0.33, 0, 0.07}}, {"organs", 1}}),
            "/tissue/organs: unknown key (allowed: patient, entry, tissues, stick)");
}

}  // namespace
}  // namespace needle::haptics::anatomy
