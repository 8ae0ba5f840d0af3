#include "haptics/sim/force_sensor.hpp"

#include <cmath>

namespace needle::haptics {

ForceSensor::ForceSensor(ForceSensorParams params) : params_(params), rng_(params.seed) {}

void ForceSensor::reset(const Wrench& truth) { filtered_ = truth; }

Wrench ForceSensor::read(const Wrench& truth, double dt) {
  const double gain = 1.0 - std::exp(-2.0 * M_PI * params_.bandwidth_Hz * dt);  // exact discrete first order
  filtered_ += gain * (truth - filtered_);
  Wrench out = filtered_ + params_.bias;
  for (int i = 0; i < 6; ++i) out[i] += (i < 3 ? params_.force_noise_N : params_.torque_noise_Nm) * unit_(rng_);
  return out;
}

}  // namespace needle::haptics
