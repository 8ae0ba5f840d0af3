// Every field of Metrics with its name and how the panels show it, visited in one fixed order: the
// one list the session store, the JSON and CSV exports and the panels read, so a new metric is
// added in one place.
#pragma once

#include <type_traits>

#include "training/scoring/metrics.hpp"
#include "training/scoring/score.hpp"

namespace needle::training {

// How the panels show a metric: its label in a clinician's words and its unit, the factor from its
// stored SI value (or, for the normalized jerk, the score's smoothness, 0 to 1), the decimals worth
// reading, and whether it is the layered tissue's (shown only for a session on one). No label: not shown.
struct MetricLabel {
  const char* label = nullptr;
  const char* unit = "";
  double scale = 1.0;
  bool layered = false;
  int decimals = 2;
  double (*convert)(double) = nullptr;  // instead of the scale, when set
  double shown(double stored) const { return convert ? convert(stored) : stored * scale; }
};

// The normalized jerk as the score reads it, 1 at a minimum-jerk movement, 0 at the default reference
// (docs/SCORING.md, "Smoothness"): the number a reader compares, where the jerk spans decades.
inline double smoothness_shown(double normalized_jerk) {
  return std::isnan(normalized_jerk) ? normalized_jerk
                                     : smoothness_score(normalized_jerk, ScoreReferences{}.normalized_jerk);
}

// Calls f(name, field) for each field; field is a double& or a uint32_t& (const if m is). An f
// that takes a third argument, f(name, field, label), is also given how the panels show it.
template <class M, class F>
void for_each_metric(M& m, F&& f) {
  const auto visit = [&f](const char* name, auto& field, const MetricLabel& label) {
    if constexpr (std::is_invocable_v<F&, const char*, decltype(field), const MetricLabel&>)
      f(name, field, label);
    else
      f(name, field);
  };
  visit("duration_s", m.duration_s, {"time taken", "s", 1.0, false, 1});
  visit("tissue_time_s", m.tissue_time_s, {"time in tissue", "s", 1.0, false, 1});
  visit("tip_error_m", m.tip_error_m, {"tip to target", "mm", 1000.0, false, 1});
  visit("axis_deviation_deg", m.axis_deviation_deg, {"off the planned axis", "deg", 1.0, false, 1});
  visit("lateral_load_Ns", m.lateral_load_Ns, {"sideways load on the needle, over time", "N s", 1.0, false, 1});
  visit("lateral_peak_N", m.lateral_peak_N, {"sideways load on the needle, peak", "N"});
  visit("peak_hand_force_N", m.peak_hand_force_N, {"force at the hand, peak", "N"});
  visit("peak_axial_force_N", m.peak_axial_force_N, {"force along the needle, peak", "N"});
  visit("peak_needle_force_N", m.peak_needle_force_N, {"force on the needle, peak", "N"});
  visit("peak_force_N", m.peak_force_N, {"force on bone or a rigid surface, peak", "N"});
  visit("force_limited_s", m.force_limited_s, {"device at its force limit", "s", 1.0, false, 1});
  visit("passivity_damped_s", m.passivity_damped_s, {"force damped to keep it stable", "s", 1.0, false, 1});
  visit("force_sd_N", m.force_sd_N, {"force held: its wobble (SD)", "N"});
  visit("path_length_m", m.path_length_m, {"tip's path", "mm", 1000.0, false, 0});
  visit("ideal_path_m", m.ideal_path_m, {"straight-line distance", "mm", 1000.0, false, 0});
  visit("normalized_jerk", m.normalized_jerk, {"smoothness", "0-1, 1 smoothest", 1.0, false, 2, smoothness_shown});
  visit("needle_visibility", m.needle_visibility, {"needle in the ultrasound image", "share"});
  visit("withdrawals", m.withdrawals, {"withdrawals", "count", 1.0, false, 0});
  visit("reinsertions", m.reinsertions, {"re-insertions", "count", 1.0, false, 0});
  visit("rigid_contacts", m.rigid_contacts, {"bumps on a rigid surface", "count", 1.0, false, 0});
  visit("faults", m.faults, {"safety stops", "count", 1.0, false, 0});
  visit("first_fault", m.first_fault, {"first safety stop", "cause", 1.0, false, 0});
  visit("punctures", m.punctures, {"membranes punctured", "count", 1.0, true, 0});
  visit("overshoot_m", m.overshoot_m, {"overshoot after the give", "mm", 1000.0, true, 1});
  visit("bone_contacts", m.bone_contacts, {"bone contacts", "count", 1.0, true, 0});
  visit("bone_peak_force_N", m.bone_peak_force_N, {"force on bone, peak", "N", 1.0, true, 1});
  visit("redirections", m.redirections, {"redirections", "count", 1.0, true, 0});
  visit("forbidden_punctures", m.forbidden_punctures, {"forbidden punctures (the dura)", "count", 1.0, true, 0});
  visit("interspace_entered", m.interspace_entered, {"interspace entered (1 = L1-L2)", "-", 1.0, true, 0});
  visit("entry_angle_deg", m.entry_angle_deg, {"needle off the approach at entry", "deg", 1.0, true, 1});
  visit("lor_depth_m", m.lor_depth_m, {"depth at the loss of resistance", "mm", 1000.0, true, 1});
  visit("lor_depth_error_m", m.lor_depth_error_m,
        {"loss of resistance past the patient's depth", "mm", 1000.0, true, 1});
  visit("advance_after_loss_m", m.advance_after_loss_m,
        {"advanced after the loss of resistance", "mm", 1000.0, true, 1});
  visit("loss_pressure_before_Pa", m.loss_pressure_before_Pa,
        {"plunger pressure before the loss", "kPa", 1e-3, true, 1});
  visit("loss_pressure_after_Pa", m.loss_pressure_after_Pa, {"plunger pressure after the loss", "kPa", 1e-3, true, 1});
  visit("false_losses", m.false_losses, {"false losses of resistance", "count", 1.0, true, 0});
  visit("pressure_applied_s", m.pressure_applied_s, {"plunger pressed", "s", 1.0, true, 1});
}

// How the panels show the metric called `name` (its field's name); no label when none has it.
inline MetricLabel metric_label(const std::string& name) {
  MetricLabel out;
  const Metrics none;
  for_each_metric(none, [&](const char* field, const auto&, const MetricLabel& shown) {
    if (name == field) out = shown;
  });
  return out;
}

}  // namespace needle::training
