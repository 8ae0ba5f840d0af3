#include "haptics/sim/work_precision.hpp"

#include <chrono>
#include <cmath>

#include "haptics/constraints/pfaffian.hpp"
#include "haptics/model/dynamics.hpp"
#include "haptics/model/kinematics.hpp"

namespace needle::haptics {
namespace {

struct Run {
  VecN q, dq;
  double drift = 0;
  double seconds = 0;
  long steps = 0;
};

Run integrate(const PrecisionProblem& p, Integrator integrator, double dt) {
  const RobotModel& model = *p.model;
  RobotData data(model);
  NonholonomicMultiplier multiplier(p.gains);
  multiplier.reset(2);
  TaskPfaffian task;
  MatKN A, A_dot;
  VecK lambda;
  Run run{p.q0, p.dq0};
  auto accel = [&](const VecN& q, const VecN& dq, VecN& ddq) {
    update_frames(model, data, q, dq);
    update_tick_dynamics(model, data);  // the servo tick's path
    needle_pfaffian(data.tip.linear(), data.tip_twist.tail<3>(), task);
    project_pfaffian(task, data.J, data.Jdot, A, A_dot);
    multiplier.solve(model, data, A, A_dot, p.tau, lambda, ddq);
  };
  run.steps = std::lround(p.horizon_s / dt);
  const auto t0 = std::chrono::steady_clock::now();
  for (long k = 0; k < run.steps; ++k) {
    integrate_step(integrator, run.q, run.dq, dt, accel);
  }
  update_kinematics(model, data, run.q, run.dq);
  needle_pfaffian(data.tip.linear(), data.tip_twist.tail<3>(), task);
  project_pfaffian(task, data.J, data.Jdot, A, A_dot);
  run.drift = (A * run.dq).norm();
  run.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return run;
}

}  // namespace

VecN reference_solution(const PrecisionProblem& problem, double dt) {
  return integrate(problem, Integrator::Rk4, dt).q;
}

PrecisionRow run_precision(const PrecisionProblem& problem, Integrator integrator, double dt, const VecN* q_reference) {
  const Run run = integrate(problem, integrator, dt);
  PrecisionRow row{integrator, dt, run.steps, 1e6 * run.seconds / static_cast<double>(run.steps), 0.0, run.drift};
  if (q_reference) row.error = (run.q - *q_reference).norm();
  return row;
}

double fitted_order(std::span<const PrecisionRow> rows, double floor) {
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  int n = 0;
  for (const PrecisionRow& r : rows) {
    if (!(r.error > floor)) continue;
    const double x = std::log(r.dt_s), y = std::log(r.error);
    sx += x, sy += y, sxx += x * x, sxy += x * y;
    ++n;
  }
  if (n < 2) return std::nan("");
  return (n * sxy - sx * sy) / (n * sxx - sx * sx);
}

}  // namespace needle::haptics
