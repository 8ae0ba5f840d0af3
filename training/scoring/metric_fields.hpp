// Every field of Metrics with its name and how the panels show it, visited in one fixed order: the
// one list the session store, the JSON and CSV exports and the panels read, so a new metric is
// added in one place.
#pragma once

#include <type_traits>

#include "training/scoring/metrics.hpp"

namespace needle::training {

// How the panels show a metric: its label and unit, the factor from its stored SI value, and
// whether it is the layered tissue's (shown only for a session on one). No label: not shown.
struct MetricLabel {
  const char* label = nullptr;
  const char* unit = "";
  double scale = 1.0;
  bool layered = false;
};

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
  visit("duration_s", m.duration_s, {"duration", "s"});
  visit("tip_error_m", m.tip_error_m, {"tip to target", "mm", 1000.0});
  visit("axis_deviation_deg", m.axis_deviation_deg, {"off axis", "deg"});
  visit("lateral_load_Ns", m.lateral_load_Ns, {"lateral load", "N s"});
  visit("lateral_peak_N", m.lateral_peak_N, {"lateral peak", "N"});
  visit("peak_hand_force_N", m.peak_hand_force_N, {"peak force at the hand", "N"});
  visit("peak_axial_force_N", m.peak_axial_force_N, {"peak along the needle", "N"});
  visit("peak_needle_force_N", m.peak_needle_force_N, {"peak on the needle", "N"});
  visit("peak_force_N", m.peak_force_N, {"peak rigid contact", "N"});
  visit("force_limited_s", m.force_limited_s, {"at the device's limit", "s"});
  visit("passivity_damped_s", m.passivity_damped_s, {"passivity damper on", "s"});
  visit("force_sd_N", m.force_sd_N, {"force SD", "N"});
  visit("path_length_m", m.path_length_m, {"path", "mm", 1000.0});
  visit("ideal_path_m", m.ideal_path_m, {"ideal path", "mm", 1000.0});
  visit("normalized_jerk", m.normalized_jerk, {"normalized jerk", "-"});
  visit("needle_visibility", m.needle_visibility, {});
  visit("withdrawals", m.withdrawals, {"withdrawals", "count"});
  visit("reinsertions", m.reinsertions, {"re-insertions", "count"});
  visit("rigid_contacts", m.rigid_contacts, {"rigid contacts", "count"});
  visit("faults", m.faults, {"safety faults", "count"});
  visit("first_fault", m.first_fault, {"first fault", "cause"});
  visit("punctures", m.punctures, {"punctures", "count", 1.0, true});
  visit("overshoot_m", m.overshoot_m, {"overshoot", "mm", 1000.0, true});
  visit("bone_contacts", m.bone_contacts, {"bone contacts", "count", 1.0, true});
  visit("bone_peak_force_N", m.bone_peak_force_N, {"bone peak force", "N", 1.0, true});
  visit("redirections", m.redirections, {"redirections", "count", 1.0, true});
  visit("forbidden_punctures", m.forbidden_punctures, {"forbidden punctures", "count", 1.0, true});
  visit("interspace_entered", m.interspace_entered, {"interspace entered (1 = L1-L2)", "-", 1.0, true});
  visit("entry_angle_deg", m.entry_angle_deg, {"needle off the approach at entry", "deg", 1.0, true});
  visit("lor_depth_m", m.lor_depth_m, {"depth at the loss of resistance", "mm", 1000.0, true});
  visit("lor_depth_error_m", m.lor_depth_error_m, {"loss of resistance past the patient's depth", "mm", 1000.0, true});
  visit("advance_after_loss_m", m.advance_after_loss_m, {"advanced after the loss", "mm", 1000.0, true});
  visit("loss_pressure_before_Pa", m.loss_pressure_before_Pa, {"plunger pressure before the loss", "kPa", 1e-3, true});
  visit("loss_pressure_after_Pa", m.loss_pressure_after_Pa, {"plunger pressure after the loss", "kPa", 1e-3, true});
  visit("false_losses", m.false_losses, {"false losses of resistance", "count", 1.0, true});
  visit("pressure_applied_s", m.pressure_applied_s, {"plunger pressed", "s", 1.0, true});
}

}  // namespace needle::training
