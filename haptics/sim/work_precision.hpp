// Work-precision study of the virtual robot's constrained dynamics: the needle in tissue
// (multipliers (3.22) with the stabilization (3.23), β = 0 so the state is (q, q̇)) under a
// constant torque, integrated over a horizon with each integrator and step, against a reference
// run (RK4 at a much smaller step). For `needle-sim bench precision` and its test.
#pragma once

#include <span>
#include <vector>

#include "haptics/constraints/nonholonomic_multiplier.hpp"
#include "haptics/sim/integrator.hpp"

namespace needle::haptics {

struct PrecisionProblem {
  const RobotModel* model = nullptr;
  VecN q0, dq0, tau;
  double horizon_s = 0.256;  // a multiple of every benchmarked step
  NonholonomicGains gains{50.0, 0.0};
};

struct PrecisionRow {
  Integrator integrator;
  double dt_s = 0;
  long steps = 0;
  double time_per_step_us = 0;
  double error = 0;  // |q(T) − q_ref(T)|, rad
  double drift = 0;  // |A q̇| at the end: lateral tip speed left, m/s
};

// One run, timed; error against q_reference when given.
PrecisionRow run_precision(const PrecisionProblem& problem, Integrator integrator, double dt, const VecN* q_reference);
VecN reference_solution(const PrecisionProblem& problem, double dt);

// Least-squares slope of log(error) against log(dt) over rows whose error is above `floor`.
double fitted_order(std::span<const PrecisionRow> rows, double floor = 1e-12);

}  // namespace needle::haptics
