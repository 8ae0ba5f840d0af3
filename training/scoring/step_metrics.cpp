#include "training/scoring/step_metrics.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <numbers>

namespace needle::training {

StepMetricsAccumulator::StepMetricsAccumulator(const Task& task, const Step& step) : task_(task), step_(step) {
  const Condition& c = step.condition;
  target_ = c.type == ConditionType::kTargetReached ? c.marker : step.guidance.target;
  deviation_at_end_ = c.type == ConditionType::kAxisAligned;
  axis_ = deviation_at_end_ ? c.marker : step.guidance.axis;
  planned_rigid_ = c.contact == ContactRequirement::kRigidSurface;
  if (task.syringe) m_.false_losses = m_.pressure_applied_s = 0.0;
}

void StepMetricsAccumulator::add(const haptics::ToolSnapshot& state, const ContactEvents& events) {
  const double t = state.time_s;
  const double dt = samples_ ? t - t_prev_ : 0.0;
  tip_ = vec3(state.needle_tip_m);
  path_.add(t, tip_);
  if (axis_ >= 0) {
    last_deviation_rad_ = angle_between(haptics::needle_axis(state), planned_direction(task_.markers[axis_], tip_));
    deviation_sq_sum_ += last_deviation_rad_ * last_deviation_rad_;
  }
  const double lateral = lateral_load_N(state);
  m_.lateral_load_Ns += 0.5 * (lateral + lateral_prev_) * dt;  // trapezoid
  m_.lateral_peak_N = std::max(m_.lateral_peak_N, lateral);
  lateral_prev_ = lateral;
  const double force = norm(vec3(state.environment_force_n));
  m_.peak_force_N = std::max(m_.peak_force_N, force);
  const NeedleForce needle = needle_force(state);
  m_.peak_axial_force_N = std::max(m_.peak_axial_force_N, std::abs(needle.along_N));
  m_.peak_needle_force_N = std::max(m_.peak_needle_force_N, needle.total_N);
  m_.peak_hand_force_N = std::max(m_.peak_hand_force_N, task_.force_scale * needle.total_N);
  if (state.contact == haptics::ContactState::kTissue) m_.tissue_time_s += dt;
  if (state.limits & haptics::kLimitForce) m_.force_limited_s += dt;
  if (state.limits & haptics::kLimitPassivityDamper) m_.passivity_damped_s += dt;
  if (step_.condition.type == ConditionType::kForceHeld) {
    in_band_seen_ = in_band_seen_ || (force >= step_.condition.min && force <= step_.condition.max);
    if (in_band_seen_) {
      const double delta = force - force_mean_;
      force_mean_ += delta / static_cast<double>(++force_n_);
      force_m2_ += delta * (force - force_mean_);
    }
  }
  // Trapezoids between consecutive states in tissue: a time mean of the share in the slice.
  const bool in_tissue = events.entry != nullptr && task_.ultrasound_probe.has_value();
  const double visible = in_tissue ? share_in_image_slice(*task_.ultrasound_probe, *events.entry, tip_) : 0.0;
  if (in_tissue && in_tissue_prev_) {
    visible_integral_s_ += 0.5 * (visible + visible_prev_) * dt;
    tissue_time_s_ += dt;
  }
  in_tissue_prev_ = in_tissue;
  visible_prev_ = visible;
  m_.withdrawals += events.withdrawal;
  m_.reinsertions += events.reinsertion;
  m_.rigid_contacts += events.rigid_entry && !planned_rigid_;
  if (const LayerEvents* l = events.layers) {
    m_.punctures += uint32_t(std::popcount(l->punctured));
    m_.forbidden_punctures += uint32_t(std::popcount(l->passed & step_.forbidden_punctures));
    m_.bone_contacts += l->bone_entry;
    m_.redirections += l->redirection;
    if (l->punctured || run_m_ >= 0.0) run_m_ = l->run_m;  // a run that began in this step or before, still followed
  }
  if (const SyringeEvents* y = events.syringe) {
    if (y->pressing) m_.pressure_applied_s += dt;
    m_.false_losses += y->false_loss;
    if (y->loss) m_.loss_pressure_before_Pa = y->pressure_before_Pa;
    if (y->loss_settled) m_.loss_pressure_after_Pa = y->pressure_after_Pa;
    if (y->advance_m >= 0.0) m_.advance_after_loss_m = y->advance_m;  // since the loss, in this step or an earlier one
  }
  if (state.tissue.bone_layer >= 0)
    m_.bone_peak_force_N = std::max(m_.bone_peak_force_N, norm(vec3(state.tissue.bone_force_n)));
  if (events.fault) {
    if (m_.faults++ == 0) m_.first_fault = state.fault;
  }
  t_prev_ = t;
  ++samples_;
}

Metrics StepMetricsAccumulator::result() const {
  Metrics m = m_;
  m.duration_s = path_.duration_s();
  m.path_length_m = path_.length_m();
  m.ideal_path_m = path_.chord_m();
  m.normalized_jerk = path_.normalized_jerk();
  if (samples_ == 0) return m;
  if (target_ >= 0) m.tip_error_m = distance(tip_, task_.markers[target_].position);
  if (axis_ >= 0) {
    const double rad = deviation_at_end_ ? last_deviation_rad_ : std::sqrt(deviation_sq_sum_ / double(samples_));
    m.axis_deviation_deg = rad * 180.0 / std::numbers::pi;
  }
  if (force_n_ > 0) m.force_sd_N = std::sqrt(force_m2_ / double(force_n_));
  if (tissue_time_s_ > 0.0) m.needle_visibility = visible_integral_s_ / tissue_time_s_;
  if (run_m_ >= 0.0) m.overshoot_m = run_m_;
  return m;
}

}  // namespace needle::training
