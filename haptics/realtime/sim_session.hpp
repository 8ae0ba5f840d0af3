// A `sim` run ready for the loop: the scenario, the simulated master device and the
// controller step, all at the loop's period. One object, so their lifetimes cannot cross.
#pragma once

#include <string>

#include "haptics/devices/sim_device.hpp"
#include "haptics/realtime/teleoperation_step.hpp"
#include "haptics/sim/scenario.hpp"

namespace needle::haptics {

class SimSession {
 public:
  // Throws ScenarioError naming the file; std::invalid_argument for a rate outside 250..10000 Hz.
  SimSession(const std::string& scenario_path, double rate_hz);
  SimSession(Scenario scenario, double rate_hz);
  SimSession(const SimSession&) = delete;
  SimSession& operator=(const SimSession&) = delete;

  const Scenario& scenario() const noexcept { return scenario_; }
  SimDevice& device() noexcept { return device_; }
  TeleoperationStep& step() noexcept { return step_; }

 private:
  Scenario scenario_;
  SimDevice device_;
  TeleoperationStep step_;
};

}  // namespace needle::haptics
