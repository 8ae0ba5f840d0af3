// The integrators converge at their theoretical order on the constrained virtual robot, and the
// stabilized constraint does not drift.
#include <gtest/gtest.h>

#include "haptics/model/kinematics.hpp"
#include "haptics/sim/work_precision.hpp"
#include "robot_fixtures.hpp"

namespace needle::haptics {
namespace {

double initial_lateral_speed(const PrecisionProblem& p) {
  RobotData d(*p.model);
  update_kinematics(*p.model, d, p.q0, p.dq0);
  return std::hypot(d.tip.linear().col(1).dot(d.tip_twist.head<3>()), d.tip.linear().col(2).dot(d.tip_twist.head<3>()));
}

TEST(BenchPrecision, IntegratorsConvergeAtTheirOrder) {
  const RobotModel model = test::virtual_robot();
  PrecisionProblem p;
  p.model = &model;
  p.q0 = (VecN(5) << 0.0, 1.0, -1.6, 0.0, 0.5).finished();
  p.dq0 = (VecN(5) << 0.2, -0.3, 0.4, 0.5, -0.5).finished();
  p.tau = VecN::Constant(5, 0.01);
  p.horizon_s = 0.048;
  const VecN reference = reference_solution(p, 2.5e-4 / 16);
  for (Integrator integrator : {Integrator::SemiImplicitEuler, Integrator::Rk4}) {
    std::vector<PrecisionRow> rows;
    for (double dt : {2e-3, 1e-3, 5e-4, 2.5e-4}) rows.push_back(run_precision(p, integrator, dt, &reference));
    EXPECT_NEAR(fitted_order(rows), integrator_order(integrator), 0.35) << integrator_name(integrator);
    // The stabilization (3.23) has decayed the starting lateral tip speed by e^{-αT} ≈ 0.09.
    for (const PrecisionRow& r : rows) EXPECT_LT(r.drift, 0.15 * initial_lateral_speed(p)) << r.dt_s;
  }
}

TEST(BenchPrecision, FittedOrderIsTheSlopeOfAPowerLaw) {
  std::vector<PrecisionRow> rows;
  for (double dt : {1e-2, 1e-3, 1e-4}) rows.push_back({Integrator::Rk4, dt, 1, 0, 7.0 * std::pow(dt, 3), 0});
  EXPECT_NEAR(fitted_order(rows), 3.0, 1e-12);
}

}  // namespace
}  // namespace needle::haptics
