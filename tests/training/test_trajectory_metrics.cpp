// Path length and normalized jerk against trajectories with closed-form answers, sampled at the
// 1 kHz servo rate.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <numbers>

#include "training/scoring/trajectory_metrics.hpp"

namespace needle::training {
namespace {
constexpr double kPi = std::numbers::pi;

PathAccumulator sampled(double duration_s, const std::function<Vec3(double)>& p, double dt = 0.001) {
  PathAccumulator path;
  const long n = std::lround(duration_s / dt);
  for (long k = 0; k <= n; ++k) path.add(k * dt, p(k * dt));
  return path;
}

TEST(TrajectoryMetrics, StraightLineAtConstantSpeedHasItsLengthAndNoJerk) {
  const Vec3 dir{2.0 / 7, 3.0 / 7, 6.0 / 7};  // unit
  const PathAccumulator path = sampled(4.0, [&](double t) { return Vec3{0.1, 0.0, 0.2} + (0.05 * t) * dir; });
  EXPECT_NEAR(path.length_m(), 0.2, 1e-12);
  EXPECT_NEAR(path.chord_m(), 0.2, 1e-12);
  EXPECT_DOUBLE_EQ(path.duration_s(), 4.0);
  EXPECT_NEAR(path.normalized_jerk(), 0.0, 1e-4);
}

TEST(TrajectoryMetrics, CircleAtConstantSpeed) {
  // R = 5 cm, omega = 0.15 pi rad/s for 10 s (three quarters of a turn): |jerk| = R omega^3,
  // L = R omega T, so NJ = sqrt(T^5 / (2 L^2) * R^2 omega^6 T) = omega^2 T^2 / sqrt(2).
  const double R = 0.05, w = 0.15 * kPi, T = 10.0;
  const PathAccumulator path = sampled(T, [&](double t) {
    return Vec3{R * std::cos(w * t), R * std::sin(w * t), 0.3};
  });
  EXPECT_NEAR(path.length_m(), R * w * T, 1e-8);           // chords of 1 ms: relative error (w dt)^2 / 24
  EXPECT_NEAR(path.chord_m(), R * std::sqrt(2.0), 1e-12);  // start to end across a quarter-turn gap
  EXPECT_NEAR(path.normalized_jerk(), w * w * T * T / std::sqrt(2.0), 1e-3 * w * w * T * T);
}

TEST(TrajectoryMetrics, ConstantJerkFromRestGivesSqrt18WhateverTheScale) {
  // x = J t^3 / 6: integral of J^2 over T is J^2 T, L = J T^3 / 6, NJ = sqrt(18).
  for (const double J : {0.01, 0.3}) {
    const PathAccumulator path = sampled(3.0, [&](double t) { return Vec3{J * t * t * t / 6.0, 0.0, 0.0}; });
    EXPECT_NEAR(path.normalized_jerk(), std::sqrt(18.0), 1e-6) << J;
  }
}

TEST(TrajectoryMetrics, MinimumJerkReachGivesSqrt360) {
  // x = L (10 s^3 - 15 s^4 + 6 s^5), s = t/T: jerk = L/T^3 (60 - 360 s + 360 s^2), whose square
  // integrates to 720 L^2 / T^5, so NJ = sqrt(360). The third difference misses the first and
  // last 1.5 decimation steps (0.03 s of 10 s each), where j^2 is 5 times its mean: the
  // integral comes out about 2 x 0.003 x (5 - 1) = 2.4 % low, NJ 1.2 %.
  const double L = 0.08, T = 10.0;
  const PathAccumulator path = sampled(T, [&](double t) {
    const double s = t / T;
    return Vec3{0.0, L * (10 * s * s * s - 15 * s * s * s * s + 6 * s * s * s * s * s), 0.0};
  });
  EXPECT_NEAR(path.length_m(), L, 1e-12);
  EXPECT_NEAR(path.normalized_jerk(), std::sqrt(360.0), 0.015 * std::sqrt(360.0));
  EXPECT_LT(path.normalized_jerk(), std::sqrt(360.0));  // the missed ends only lower it
}

TEST(TrajectoryMetrics, ServoRateJitterIsNotJerk) {
  // 1 um of jitter at 250 Hz on a slow straight line: differenced at 1 kHz it would be a jerk
  // of 1e-6 (2 pi 250)^3 = 3.9e3 m/s^3; decimated to 50 Hz it stays a small fraction of that.
  const PathAccumulator path = sampled(4.0, [](double t) {
    return Vec3{0.02 * t + 1e-6 * std::sin(2 * kPi * 250 * t), 0, 0};
  });
  const double at_servo_rate =
      std::sqrt(0.5 * std::pow(2 * kPi * 250, 6) * 0.5e-12 * 4.0 * std::pow(4.0, 5) / (0.08 * 0.08));
  EXPECT_LT(path.normalized_jerk(), 1e-3 * at_servo_rate);
}

TEST(TrajectoryMetrics, HoldsAndShortRecordsHaveNoSmoothness) {
  EXPECT_TRUE(std::isnan(sampled(2.0, [](double) { return Vec3{0.1, 0.1, 0.1}; }).normalized_jerk()));
  EXPECT_TRUE(std::isnan(sampled(2.0, [](double t) { return Vec3{0.002 * t, 0, 0}; }).normalized_jerk()));  // 4 mm
  EXPECT_TRUE(std::isnan(sampled(0.05, [](double t) { return Vec3{t, 0, 0}; }).normalized_jerk()));  // 3 decimated
  EXPECT_DOUBLE_EQ(PathAccumulator().length_m(), 0.0);
}

}  // namespace
}  // namespace needle::training
