// Every field of Metrics with its name, visited in one fixed order: the one list the session
// store, the JSON and CSV exports and the panels read, so a new metric is added in one place.
#pragma once

#include "training/scoring/metrics.hpp"

namespace needle::training {

// Calls f(name, field) for each field; field is a double& or a uint32_t& (const if m is).
template <class M, class F>
void for_each_metric(M& m, F&& f) {
  f("duration_s", m.duration_s);
  f("tip_error_m", m.tip_error_m);
  f("axis_deviation_deg", m.axis_deviation_deg);
  f("lateral_load_Ns", m.lateral_load_Ns);
  f("lateral_peak_N", m.lateral_peak_N);
  f("peak_force_N", m.peak_force_N);
  f("peak_axial_force_N", m.peak_axial_force_N);
  f("peak_needle_force_N", m.peak_needle_force_N);
  f("peak_hand_force_N", m.peak_hand_force_N);
  f("force_limited_s", m.force_limited_s);
  f("passivity_damped_s", m.passivity_damped_s);
  f("force_sd_N", m.force_sd_N);
  f("path_length_m", m.path_length_m);
  f("ideal_path_m", m.ideal_path_m);
  f("normalized_jerk", m.normalized_jerk);
  f("needle_visibility", m.needle_visibility);
  f("withdrawals", m.withdrawals);
  f("reinsertions", m.reinsertions);
  f("rigid_contacts", m.rigid_contacts);
  f("faults", m.faults);
  f("first_fault", m.first_fault);
  f("punctures", m.punctures);
  f("overshoot_m", m.overshoot_m);
  f("bone_contacts", m.bone_contacts);
  f("bone_peak_force_N", m.bone_peak_force_N);
  f("redirections", m.redirections);
  f("forbidden_punctures", m.forbidden_punctures);
}

}  // namespace needle::training
