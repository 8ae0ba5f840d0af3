// A 6-axis force/torque sensor between the hand and the stylus: first-order low-pass at a stated
// bandwidth, constant bias and white Gaussian noise. Defaults: noise of the order of the
// resolution of the ATI Nano17 the thesis used (1/320 N, 1/64 N·mm in its SI-12-0.12
// calibration); bias 0.02 N and a 500 Hz acquisition filter are design values of this model.
#pragma once

#include <random>

#include "haptics/control/teleoperation.hpp"

namespace needle::haptics {

struct ForceSensorParams {
  Wrench bias = (Wrench() << 0.02, -0.01, 0.015, 0.0, 0.0, 0.0).finished();
  double force_noise_N = 1.0 / 320.0;
  double torque_noise_Nm = 1.0 / 64.0 / 1000.0;
  double bandwidth_Hz = 500.0;
  unsigned seed = 1;
};

class ForceSensor {
 public:
  explicit ForceSensor(ForceSensorParams params);
  void reset(const Wrench& truth);  // filter settled at `truth`
  // One sample after `dt` of the true wrench `truth`.
  Wrench read(const Wrench& truth, double dt);

 private:
  ForceSensorParams params_;
  std::mt19937 rng_;
  std::normal_distribution<double> unit_{0.0, 1.0};
  Wrench filtered_ = Wrench::Zero();
};

}  // namespace needle::haptics
