#include "haptics/sim/integrator.hpp"

#include "haptics/model/dynamics.hpp"
#include "haptics/model/kinematics.hpp"

namespace needle::haptics {

std::string_view integrator_name(Integrator integrator) {
  return integrator == Integrator::Rk4 ? "rk4" : "semi_implicit_euler";
}

int integrator_order(Integrator integrator) { return integrator == Integrator::Rk4 ? 4 : 1; }

void integrate_step(Integrator integrator, const RobotModel& model, RobotData& data, VecN& q, VecN& dq, const VecN& tau,
                    double h) {
  integrate_step(integrator, q, dq, h, [&](const VecN& qs, const VecN& vs, VecN& a) {
    update_kinematics(model, data, qs, vs);
    update_dynamics(model, data);
    forward_dynamics(model, data, tau, a);
  });
  update_kinematics(model, data, q, dq);
  update_dynamics(model, data);
}

}  // namespace needle::haptics
