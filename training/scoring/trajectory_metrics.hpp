// Streaming kinematic metrics of the tip path: length and normalized jerk. Fixed-size state,
// no allocation: fed one sample at a time.
//
// Jerk is differenced from positions decimated to one every kJerkStep_s: three differences at
// the servo rate would turn micrometre sensor jitter into jerk larger than any movement's
// (amplitude x omega^3), while voluntary hand movement lies below 10 Hz.
#pragma once

#include "training/tasks/vec3.hpp"

namespace needle::training {

class PathAccumulator {
 public:
  static constexpr double kJerkStep_s = 0.02;
  // Paths shorter than this (start to end) are holds, not movements: no smoothness for them.
  static constexpr double kMinMovement_m = 0.005;

  void add(double t, const Vec3& p);
  double length_m() const { return length_; }
  double chord_m() const { return count_ ? distance(first_, last_) : 0.0; }  // start to end
  double duration_s() const { return count_ ? t_last_ - t_first_ : 0.0; }
  // sqrt(T^5 / (2 L^2) * integral |d3p/dt3|^2 dt) (Teulings et al. 1997); NaN before four
  // decimated samples or when the start-to-end distance is below kMinMovement_m. The third
  // difference has no value in the first and last 1.5 decimation steps: the integral is the
  // mean square jerk where it has one, times T.
  double normalized_jerk() const;

 private:
  int count_ = 0;
  double t_first_ = 0.0, t_last_ = 0.0;
  Vec3 first_{}, last_{};
  double length_ = 0.0;
  // Backward differences of the decimated positions: the last position, velocity and
  // acceleration, with their times.
  int decimated_ = 0;
  double tp_ = 0.0;
  Vec3 p_{}, v_{}, a_{};
  double tv_ = 0.0, ta_ = 0.0;
  double jerk_sq_integral_ = 0.0;
  double jerk_span_s_ = 0.0;  // time the integral covers
};

}  // namespace needle::training
