#include "haptics/sim/integrator.hpp"

#include "haptics/model/dynamics.hpp"
#include "haptics/model/kinematics.hpp"

namespace needle::haptics {

std::string_view integrator_name(Integrator integrator) {
  return integrator == Integrator::Rk4 ? "rk4" : "semi_implicit_euler";
}

int integrator_order(Integrator integrator) { return integrator == Integrator::Rk4 ? 4 : 1; }

namespace {
void acceleration(const RobotModel& model, RobotData& data, const VecN& q, const VecN& dq, const VecN& tau, VecN& ddq) {
  update_kinematics(model, data, q, dq);
  update_dynamics(model, data);
  forward_dynamics(model, data, tau, ddq);
}
}  // namespace

void integrate_step(Integrator integrator, const RobotModel& model, RobotData& data, VecN& q, VecN& dq, const VecN& tau,
                    double h) {
  const int n = data.n;
  if (integrator == Integrator::SemiImplicitEuler) {
    VecN a(n);
    acceleration(model, data, q, dq, tau, a);
    dq += h * a;
    q += h * dq;
  } else {
    VecN a1(n), a2(n), a3(n), a4(n);
    acceleration(model, data, q, dq, tau, a1);
    const VecN v1 = dq;
    const VecN v2 = dq + 0.5 * h * a1;
    acceleration(model, data, q + 0.5 * h * v1, v2, tau, a2);
    const VecN v3 = dq + 0.5 * h * a2;
    acceleration(model, data, q + 0.5 * h * v2, v3, tau, a3);
    const VecN v4 = dq + h * a3;
    acceleration(model, data, q + h * v3, v4, tau, a4);
    q += h / 6.0 * (v1 + 2.0 * v2 + 2.0 * v3 + v4);
    dq += h / 6.0 * (a1 + 2.0 * a2 + 2.0 * a3 + a4);
  }
  update_kinematics(model, data, q, dq);
  update_dynamics(model, data);
}

}  // namespace needle::haptics
