// One step of a robot's dynamics q̈ = H⁻¹(τ − C q̇ − D q̇ − g) with τ held constant over the step
// (zero-order hold, as a servo loop applies it). Allocation-free.
#pragma once

#include <string_view>

#include "haptics/model/robot_data.hpp"

namespace needle::haptics {

enum class Integrator {
  SemiImplicitEuler,  // q̇ += h q̈(q, q̇); q += h q̇: order 1, symplectic for conservative forces
  Rk4,                // classical Runge-Kutta: order 4
};

std::string_view integrator_name(Integrator integrator);
int integrator_order(Integrator integrator);

// Advances (q, dq) by h. On return `data` holds kinematics and dynamics at the new state.
void integrate_step(Integrator integrator, const RobotModel& model, RobotData& data, VecN& q, VecN& dq, const VecN& tau,
                    double h);

}  // namespace needle::haptics
