#include "training/scoring/patient_technique.hpp"

#include <cmath>
#include <numbers>

namespace needle::training {

PatientTechniqueTracker::PatientTechniqueTracker(const Task& task)
    : task_(task), epidural_(task.layer_index("epidural space")) {}

void PatientTechniqueTracker::feed(const haptics::ToolSnapshot& s, const Vec3* entry) {
  if (!task_.landmarks) return;
  const PatientLandmarks& l = *task_.landmarks;
  if (!entry) {
    in_ = false;
    if (s.tissue.surface_layer == 0) skin_met_ = vec3(s.tissue.surface_point_m);  // the skin is the first layer
    return;
  }
  const auto a = haptics::needle_axis(s);
  const Vec3 axis{a[0], a[1], a[2]};
  if (!in_ && interspace_ < 0) {  // the first entry into the skin
    entry_ = skin_met_.value_or(*entry);
    interspace_ = interspace_at(l, entry_);
    if (interspace_ >= 0)
      entry_angle_deg_ = angle_between(a, l.directions[size_t(interspace_)]) * 180.0 / std::numbers::pi;
  }
  in_ = true;
  if (epidural_ >= 0 && std::isnan(lor_depth_m_) && s.tissue.tip_layer == epidural_ && interspace_ >= 0) {
    lor_depth_m_ = dot(vec3(s.needle_tip_m) - entry_, axis);
    lor_error_m_ = lor_depth_m_ - l.skin_to_epidural_m[size_t(interspace_)];
  }
}

void PatientTechniqueTracker::write(Metrics& m) const {
  m.interspace_entered = interspace_ >= 0 ? double(interspace_ + 1) : kNotApplicable;
  m.entry_angle_deg = entry_angle_deg_;
  m.lor_depth_m = lor_depth_m_;
  m.lor_depth_error_m = lor_error_m_;
}

}  // namespace needle::training
