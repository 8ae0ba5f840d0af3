#include "haptics/realtime/syringe_servo_step.hpp"

#include <stdexcept>

namespace needle::haptics {

double plunger_thumb_force(const DeviceReading& reading, double travel_m) noexcept {
  switch (PlungerInput(reading.plunger_input)) {
    case PlungerInput::kThumbForce:
      return reading.plunger_force_n > 0.0 ? reading.plunger_force_n : 0.0;
    case PlungerInput::kHandlePosition: {
      const double force = kPlungerCouplingStiffness_N_per_m * (reading.plunger_position_m - travel_m);
      return force > 0.0 ? force : 0.0;
    }
    case PlungerInput::kNone:
      break;
  }
  return 0.0;
}

SyringeSnapshot syringe_snapshot(const SyringeParams& params, const SyringeState& s, int layer) noexcept {
  return {uint32_t(params.fluid), layer,         s.thumb_force_N, s.pressure_Pa, s.travel_m,
          s.flow_m3_per_s,        s.injected_m3, s.work_J};
}

SyringeServoStep::SyringeServoStep(ServoStep& inner, const Scenario& scenario) : inner_(inner), scenario_(scenario) {
  if (!scenario.syringe) throw std::invalid_argument(scenario.source + ": no syringe");
  params_ = *scenario.syringe;
  state_ = syringe_at_rest(params_);
}

void SyringeServoStep::step(const DeviceReading& reading, double dt_s, DeviceCommand& command,
                            ToolSnapshot& state) noexcept {
  inner_.step(reading, dt_s, command, state);
  const int layer = state.syringe.layer;
  const TissueModel& tissue = scenario_.scene.tissue;
  const LayerInjection* tip = layer >= 0 && layer < tissue.layer_count() && tissue.layer(layer).injection
                                  ? &*tissue.layer(layer).injection
                                  : nullptr;
  step_syringe(params_, state_, plunger_thumb_force(reading, state_.travel_m), flow_path(params_, tip), dt_s);
  state.syringe = syringe_snapshot(params_, state_, layer);
  command.plunger_force_n =
      PlungerInput(reading.plunger_input) == PlungerInput::kHandlePosition ? state_.thumb_force_N : 0.0;
  command.plunger_travel_m = state_.travel_m;
}

}  // namespace needle::haptics
