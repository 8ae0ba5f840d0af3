// The thesis's controller (haptics/control/teleoperation.hpp) as the loop's ServoStep, for a
// joint-space device (`sim`, or any master sharing the virtual robot's geometry): joints,
// velocities and the sensed wrench in, master torques out, the virtual robot's state published.
#pragma once

#include "haptics/control/teleoperation.hpp"
#include "haptics/realtime/servo_step.hpp"
#include "haptics/sim/scenario.hpp"

namespace needle::haptics {

class TeleoperationStep : public ServoStep {
 public:
  // The scenario must outlive the step. period_s is the loop's period (the controller's T).
  // Both robots start at the scenario's q0, at rest.
  TeleoperationStep(const Scenario& scenario, double period_s);

  // Velocities come from the reading when the device gives them, else by differencing
  // joint angles over dt. Torques of joints the device cannot drive are sent as zero.
  void step(const DeviceReading& reading, double dt_s, DeviceCommand& command, ToolSnapshot& state) noexcept override;
  // The torque the device was given: the controller's passivity observer sees it, not the command.
  void applied(const DeviceCommand& command) noexcept override;

  const Teleoperation& controller() const noexcept { return tele_; }

 private:
  const Scenario& scenario_;
  Teleoperation tele_;
  TickInput in_;
  VecN previous_q_;
  VecN applied_;
  bool have_previous_ = false;
};

}  // namespace needle::haptics
