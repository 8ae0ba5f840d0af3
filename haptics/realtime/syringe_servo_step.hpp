// The loss-of-resistance syringe in the servo tick: a ServoStep around the needle's own (joint or
// task space) that, after it, steps the syringe (haptics/syringe/syringe_step.hpp) with the thumb's
// force from the device's reading and the tissue holding the tip from the tick's state, and
// publishes it (ToolSnapshot::syringe) and the plunger's push back to the syringe hand
// (DeviceCommand::plunger_*). Built by the session when its scenario has a syringe; without one the
// inner step runs alone, as every recording made before the syringe replays. No allocation.
#pragma once

#include "haptics/realtime/servo_step.hpp"
#include "haptics/sim/scenario.hpp"
#include "haptics/syringe/syringe_step.hpp"

namespace needle::haptics {

// Design value: the spring that couples a position device's handle (a second Falcon) to the plunger,
// 1000 N/m: the plunger held in ligament is a wall of 1 N/mm, within the Falcon's stable stiffness;
// the handle feels the spring's force, the syringe is pressed with it.
inline constexpr double kPlungerCouplingStiffness_N_per_m = 1000.0;

// (reading, the plunger's travel) => the thumb's force on the plunger: the reading's force, or the
// coupling spring's k (y − x) for a handle pushed in by y, ≥ 0 (a hand only pushes); 0 without a hand.
double plunger_thumb_force(const DeviceReading& reading, double travel_m) noexcept;

class SyringeServoStep : public ServoStep {
 public:
  // Both must outlive the step; the scenario must have a syringe (throws std::invalid_argument).
  SyringeServoStep(ServoStep& inner, const Scenario& scenario);

  void step(const DeviceReading& reading, double dt_s, DeviceCommand& command, ToolSnapshot& state) noexcept override;
  void applied(const DeviceCommand& command) noexcept override { inner_.applied(command); }

  const SyringeState& syringe() const noexcept { return state_; }
  const SyringeParams& params() const noexcept { return params_; }

 private:
  ServoStep& inner_;
  const Scenario& scenario_;
  SyringeParams params_;
  SyringeState state_;
};

// (params, state, the opening's layer) => the snapshot's syringe fields.
SyringeSnapshot syringe_snapshot(const SyringeParams& params, const SyringeState& state, int layer) noexcept;

}  // namespace needle::haptics
