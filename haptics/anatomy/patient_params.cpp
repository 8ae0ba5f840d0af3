#include "haptics/anatomy/patient_params.hpp"

#include <cmath>

#include "io/strict_json.hpp"

namespace needle::haptics::anatomy {

const char* sex_name(Sex sex) { return sex == Sex::Female ? "female" : "male"; }
const char* posture_name(Posture posture) { return posture == Posture::SittingFlexed ? "sitting_flexed" : "lateral"; }

PatientParams read_patient(const nlohmann::json& j, const std::string& file, const std::string& at) {
  const io::StrictJsonReader<PatientError> r(file);
  r.object(j, at, {"name", "description", "height_m", "weight_kg", "sex", "age_years", "posture", "seed"});
  if (j.contains("name")) r.string(j["name"], at + "/name");
  if (j.contains("description")) r.string(j["description"], at + "/description");
  PatientParams p;
  p.height_m = r.in_range(r.member(j, at, "height_m"), at + "/height_m", kHeightRange);
  p.weight_kg = r.in_range(r.member(j, at, "weight_kg"), at + "/weight_kg", kWeightRange);
  if (!kBmiRange.contains(p.bmi()))
    r.fail(at + "/weight_kg", "gives a BMI of " + io::number_text(p.bmi()) + " with height_m " +
                                  io::number_text(p.height_m) + ": the BMI must be in " + kBmiRange.text());
  const std::string sex = r.string(r.member(j, at, "sex"), at + "/sex");
  if (sex != "female" && sex != "male") r.fail(at + "/sex", "expected \"female\" or \"male\", got \"" + sex + "\"");
  p.sex = sex == "female" ? Sex::Female : Sex::Male;
  p.age_years = r.in_range(r.member(j, at, "age_years"), at + "/age_years", kAgeRange);
  const std::string posture = r.string(r.member(j, at, "posture"), at + "/posture");
  if (posture != "sitting_flexed" && posture != "lateral")
    r.fail(at + "/posture", "expected \"sitting_flexed\" or \"lateral\", got \"" + posture + "\"");
  p.posture = posture == "sitting_flexed" ? Posture::SittingFlexed : Posture::Lateral;
  p.seed = uint32_t(r.whole(r.member(j, at, "seed"), at + "/seed", 0, 4294967295LL));
  return p;
}

PatientParams load_patient(const std::string& path) {
  return read_patient(io::read_json_file<PatientError>(path), path);
}

nlohmann::json patient_json(const PatientParams& p) {
  return {{"height_m", p.height_m},   {"weight_kg", p.weight_kg},           {"sex", sex_name(p.sex)},
          {"age_years", p.age_years}, {"posture", posture_name(p.posture)}, {"seed", p.seed}};
}

uint64_t PatientRandom::next() {
  uint64_t z = (state_ += 0x9E3779B97F4A7C15ull);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  return z ^ (z >> 31);
}

double PatientRandom::uniform() { return double(next() >> 11) * 0x1.0p-53; }

double PatientRandom::normal() {
  const double u1 = 1.0 - uniform(), u2 = uniform();  // u1 in (0, 1]
  return std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * M_PI * u2);
}

PatientParams random_patient(uint64_t seed) {
  PatientRandom rng(seed);
  const auto in = [&](const io::Range& r) { return r.lo + (r.hi - r.lo) * rng.uniform(); };
  PatientParams p;
  // Rounded as a file would give them (1 mm, 0.1 kg, a whole year), so the patient a session
  // records in JSON is exactly the one it ran.
  p.height_m = std::round(in(kRandomHeightRange)*1000.0) / 1000.0;
  p.weight_kg = std::round(in(kRandomBmiRange)*p.height_m * p.height_m * 10.0) / 10.0;
  p.age_years = std::round(in(kRandomAgeRange));
  p.sex = rng.uniform() < 0.5 ? Sex::Female : Sex::Male;
  p.posture = rng.uniform() < 0.5 ? Posture::SittingFlexed : Posture::Lateral;
  do p.seed = uint32_t(rng.next());
  while (p.seed == 0);
  return p;
}

}  // namespace needle::haptics::anatomy
