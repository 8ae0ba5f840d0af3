#include "haptics/anatomy/patient_report.hpp"

#include <cmath>

#include "haptics/tissue/kinematic_insertion.hpp"

namespace needle::haptics::anatomy {
namespace {

nlohmann::json point(const Eigen::Vector3d& p) { return {p.x(), p.y(), p.z()}; }

nlohmann::json length(const std::optional<double>& v) { return v ? nlohmann::json(*v) : nlohmann::json(nullptr); }

std::optional<double> difference(const std::optional<double>& a, const std::optional<double>& b) {
  if (!a || !b) return std::nullopt;
  return *a - *b;
}

}  // namespace

ApproachDepths approach_depths(const Patient& patient, const TissueModel& geometry, int interspace) {
  const Approach& a = patient.approaches[size_t(interspace)];
  const Eigen::Vector3d dir = a.direction(), start = a.entry - 0.01 * dir;
  std::optional<double> skin;
  ApproachDepths d;
  for (const LayerBoundary& b : layer_boundaries(geometry, start, dir, 0.2)) {
    if (b.layer < 0) continue;
    const std::string& name = patient.layers[size_t(b.layer)].name;
    if (patient.layers[size_t(b.layer)].rigid) break;  // the needle stops on bone
    auto set = [&](std::optional<double>& slot) {
      if (!slot && skin) slot = b.depth_m - *skin;
    };
    if (name == "skin" && !skin) skin = b.depth_m;
    if (name == "supraspinous ligament") set(d.supraspinous_m);
    if (name == "ligamentum flavum") set(d.flavum_m);
    if (name == "epidural space") set(d.epidural_m);
    if (name == "dura") set(d.dura_m);
  }
  return d;
}

nlohmann::json patient_report(const Patient& p) {
  nlohmann::json out;
  out["patient"] = patient_json(p.params);
  out["bmi"] = p.params.bmi();
  const PatientDimensions& d = p.spine.dims;
  nlohmann::json vertebrae = nlohmann::json::array();
  for (int l = 0; l < kLumbarLevels; ++l) {
    const VertebraDimensions& v = d.vertebrae[size_t(l)];
    vertebrae.push_back({{"level", kLevelNames[size_t(l)]},
                         {"body_height_m", v.body_height_m},
                         {"body_anterior_height_m", v.body_anterior_height_m},
                         {"body_depth_m", v.body_depth_m},
                         {"body_width_m", v.body_width_m},
                         {"canal_depth_m", v.canal_depth_m},
                         {"canal_width_m", v.canal_width_m},
                         {"pedicle_height_m", v.pedicle_height_m},
                         {"pedicle_width_m", v.pedicle_width_m},
                         {"lamina_thickness_m", v.lamina_thickness_m},
                         {"spinous_process_length_m", v.spinous_process_length_m},
                         {"spinous_process_height_m", v.spinous_process_height_m},
                         {"spinous_process_thickness_m", v.spinous_process_thickness_m},
                         {"transverse_process_span_m", v.transverse_process_span_m},
                         {"disc_posterior_height_m", v.disc_posterior_height_m},
                         {"disc_anterior_height_m", v.disc_anterior_height_m},
                         {"interlaminar_gap_m", p.spine.interspaces[size_t(l)].interlaminar_gap_m}});
  }
  out["vertebrae"] = vertebrae;
  const TissueModel geometry = geometry_model(p);
  for (int k = 0; k < 5; ++k) {
    const ApproachDepths depths = approach_depths(p, geometry, k);
    const Approach& a = p.approaches[size_t(k)];
    const double cephalad = std::atan2(a.direction().y(), -a.direction().z()) * 180.0 / M_PI;
    out[kInterspaceNames[size_t(k)]] = {
        {"skin_to_epidural_m", length(depths.epidural_m)},
        {"supraspinous_to_epidural_m", length(difference(depths.epidural_m, depths.supraspinous_m))},
        {"skin_to_dura_m", length(depths.dura_m)},
        {"skin_to_flavum_m", length(depths.flavum_m)},
        {"entry_m", point(a.entry)},
        {"window_m", point(a.window)},
        {"cephalad_angle_deg", cephalad}};
  }
  out["skin_thickness_m"] = d.skin_thickness_m;
  out["fat_thickness_m"] = p.fat_thickness_m;
  out["tuffier_line"] = {{"left_crest_m", point(p.crest_tops[0])}, {"right_crest_m", point(p.crest_tops[1])}};
  out["field_bytes"] = p.field_bytes;
  return out;
}

}  // namespace needle::haptics::anatomy
