#include "training/scoring/trajectory_metrics.hpp"

#include <cmath>

#include "training/scoring/metrics.hpp"

namespace needle::training {

// Velocity, acceleration and jerk as successive backward differences, each placed at the
// midpoint of the two values it differentiates, so uneven steps are handled.
void PathAccumulator::add(double t, const Vec3& p) {
  if (count_ == 0) {
    t_first_ = t;
    first_ = p;
  } else {
    length_ += distance(p, last_);
  }
  t_last_ = t;
  last_ = p;
  ++count_;
  if (decimated_ > 0 && t - tp_ < kJerkStep_s * (1.0 - 1e-9)) return;
  if (decimated_ >= 1) {
    const Vec3 v = (1.0 / (t - tp_)) * (p - p_);
    const double tv = 0.5 * (t + tp_);
    if (decimated_ >= 2) {
      const Vec3 a = (1.0 / (tv - tv_)) * (v - v_);
      const double ta = 0.5 * (tv + tv_);
      if (decimated_ >= 3) {
        const Vec3 j = (1.0 / (ta - ta_)) * (a - a_);
        jerk_sq_integral_ += dot(j, j) * (ta - ta_);
        jerk_span_s_ += ta - ta_;
      }
      a_ = a;
      ta_ = ta;
    }
    v_ = v;
    tv_ = tv;
  }
  p_ = p;
  tp_ = t;
  ++decimated_;
}

double PathAccumulator::normalized_jerk() const {
  if (decimated_ < 4 || chord_m() < kMinMovement_m) return kNotApplicable;
  const double T = duration_s();
  const double integral = jerk_sq_integral_ / jerk_span_s_ * T;
  return std::sqrt(0.5 * integral * std::pow(T, 5) / (length_ * length_));
}

}  // namespace needle::training
