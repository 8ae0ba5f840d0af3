#include "training/tasks/patient_session.hpp"

#include "haptics/anatomy/patient_report.hpp"

namespace needle::training {
namespace fs = std::filesystem;

namespace {

Vec3 world(const Eigen::Vector3d& model_point, const haptics::Scenario& s) {
  const Eigen::Vector3d w = model_point + s.base_in_world;
  return {w.x(), w.y(), w.z()};
}

}  // namespace

void inline_patient(const Task& task, nlohmann::json& scenario, const fs::path& scenario_folder, uint64_t seed) {
  if (!scenario.contains("tissue") || !scenario["tissue"].is_object() || !scenario["tissue"].contains("patient"))
    return;
  nlohmann::json& tissue = scenario["tissue"];
  namespace anatomy = haptics::anatomy;
  try {
    if (task.patient == "random")
      tissue["patient"] = anatomy::patient_json(anatomy::random_patient(seed));
    else if (!task.patient.empty())
      tissue["patient"] = anatomy::patient_json(anatomy::load_patient(task.patient));
    else if (tissue["patient"].is_string())
      tissue["patient"] = anatomy::patient_json(
          anatomy::load_patient((scenario_folder / tissue["patient"].get<std::string>()).string()));
  } catch (const anatomy::PatientError& e) {
    throw TaskError(e.what());
  }
  const fs::path tissues = tissue.contains("tissues") && tissue["tissues"].is_string()
                               ? scenario_folder / tissue["tissues"].get<std::string>()
                               : scenario_folder / ".." / "tissues";
  tissue["tissues"] = fs::weakly_canonical(tissues).string();
}

std::optional<PatientLandmarks> patient_landmarks(const haptics::Scenario& s) {
  if (!s.patient) return std::nullopt;
  const haptics::anatomy::Patient& p = *s.patient;
  const haptics::TissueModel geometry = haptics::anatomy::geometry_model(p);
  PatientLandmarks l;
  for (int k = 0; k < PatientLandmarks::kInterspaces; ++k) {
    const haptics::anatomy::Approach& a = p.approaches[size_t(k)];
    l.entries[size_t(k)] = world(a.entry, s);
    const Eigen::Vector3d d = a.direction();
    l.directions[size_t(k)] = {d.x(), d.y(), d.z()};
    const haptics::anatomy::ApproachDepths depths = haptics::anatomy::approach_depths(p, geometry, k);
    l.skin_to_epidural_m[size_t(k)] = depths.epidural_m.value_or(std::numeric_limits<double>::quiet_NaN());
  }
  for (size_t i = 0; i < l.spinous_tips.size(); ++i) l.spinous_tips[i] = world(p.to_model(p.spine.spinous_tips[i]), s);
  for (size_t i = 0; i < 2; ++i) l.crest_tops[i] = world(p.crest_tops[i], s);
  l.patient = haptics::anatomy::patient_json(p.params).dump();
  return l;
}

void apply_patient(Task& task, const haptics::Scenario& scenario) { task.landmarks = patient_landmarks(scenario); }

}  // namespace needle::training
