// One step of a robot's dynamics, for an acceleration that may depend on the state
// (accel(q, q̇, q̈_out)), or for q̈ = H⁻¹(τ − C q̇ − D q̇ − g) with τ held over the step
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

template <typename Accel>
void integrate_step(Integrator integrator, VecN& q, VecN& dq, double h, Accel&& accel) {
  const auto n = q.size();
  if (integrator == Integrator::SemiImplicitEuler) {
    VecN a(n);
    accel(q, dq, a);
    dq += h * a;
    q += h * dq;
    return;
  }
  VecN a1(n), a2(n), a3(n), a4(n), qs(n), v2(n), v3(n), v4(n);
  accel(q, dq, a1);
  v2 = dq + 0.5 * h * a1;
  qs = q + 0.5 * h * dq;
  accel(qs, v2, a2);
  v3 = dq + 0.5 * h * a2;
  qs = q + 0.5 * h * v2;
  accel(qs, v3, a3);
  v4 = dq + h * a3;
  qs = q + h * v3;
  accel(qs, v4, a4);
  q += h / 6.0 * (dq + 2.0 * v2 + 2.0 * v3 + v4);
  dq += h / 6.0 * (a1 + 2.0 * a2 + 2.0 * a3 + a4);
}

// Constant τ. On return `data` holds kinematics and dynamics at the new state.
void integrate_step(Integrator integrator, const RobotModel& model, RobotData& data, VecN& q, VecN& dq, const VecN& tau,
                    double h);

}  // namespace needle::haptics
