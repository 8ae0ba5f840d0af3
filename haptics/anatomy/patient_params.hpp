// Who the generated patient is: the patient file (assets/patients/*.json, docs/PATIENTS.md) read
// strictly, its ranges, and a random draw from them for a task that meets a new patient each
// attempt.
#pragma once

#include <cstdint>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>

#include "io/input_limits.hpp"

namespace needle::haptics::anatomy {

// "FILE: /json/pointer: what is wrong".
struct PatientError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

enum class Sex { Female, Male };
enum class Posture { SittingFlexed, Lateral };

struct PatientParams {
  double height_m = 1.70;
  double weight_kg = 65.0;
  Sex sex = Sex::Female;
  double age_years = 40.0;
  Posture posture = Posture::SittingFlexed;
  // 0: the population's mean for these parameters, no natural variation; otherwise the seed of
  // each dimension's variation (PatientVariation).
  uint32_t seed = 0;

  double bmi() const { return weight_kg / (height_m * height_m); }
};

// The ranges (design values): adults of 1.45 to 2.05 m (beyond about the 1st and 99th percentile
// of adult stature), 40 to 200 kg, a BMI of 16 to 60 kg/m² (severe thinness to class III obesity,
// past which the clinical depth data the generator follows stop), 18 to 90 years.
inline constexpr io::Range kHeightRange{1.45, 2.05, false, "m"};
inline constexpr io::Range kWeightRange{40.0, 200.0, false, "kg"};
inline constexpr io::Range kBmiRange{16.0, 60.0, false, "kg/m^2"};
inline constexpr io::Range kAgeRange{18.0, 90.0, false, "years"};
// What a random patient is drawn from (uniformly; design values): a stature of 1.52 to 1.92 m, a
// BMI of 18.5 to 45 (normal weight to class III obesity, the range of the clinical depth data), 18
// to 80 years, either sex, either posture.
inline constexpr io::Range kRandomHeightRange{1.52, 1.92, false, "m"};
inline constexpr io::Range kRandomBmiRange{18.5, 45.0, false, "kg/m^2"};
inline constexpr io::Range kRandomAgeRange{18.0, 80.0, false, "years"};

const char* sex_name(Sex sex);
const char* posture_name(Posture posture);

// The patient object at `at` of `file`: {height_m, weight_kg, sex, age_years, posture, seed} and
// optionally name and description. Throws PatientError "FILE: /at/key: what".
PatientParams read_patient(const nlohmann::json& patient, const std::string& file, const std::string& at = "");
// A patient file. Throws PatientError.
PatientParams load_patient(const std::string& path);
// The object read_patient reads (without name and description).
nlohmann::json patient_json(const PatientParams& p);

// A patient drawn from the random ranges by `seed` (the same seed, the same patient, on any
// machine: the draws are the project's own, not the standard library's distributions); its own
// variation seed is drawn too and is never 0.
PatientParams random_patient(uint64_t seed);

// Deterministic standard normal and uniform numbers for the patient's variation: splitmix64 and
// Box–Muller, identical on every compiler and library.
class PatientRandom {
 public:
  explicit PatientRandom(uint64_t seed) : state_(seed) {}
  uint64_t next();
  double uniform();  // [0, 1)
  double normal();

 private:
  uint64_t state_;
};

}  // namespace needle::haptics::anatomy
