#include "haptics/control/gains.hpp"

namespace needle::haptics {
namespace {

RobotGains uniform(int n, double ka, double kp, double kf, double lambda, double kbeta, double kgamma) {
  return {VecN::Constant(n, ka),    VecN::Constant(n, kp),     VecN::Constant(n, lambda),
          VecN::Constant(n, kbeta), VecN::Constant(n, kgamma), kf};
}

RobotGains thesis_virtual(int n, double kf) {
  RobotGains g = uniform(n, 0.2, 0.2, kf, 20.0, 1.0, 0.2);
  for (int i = 3; i < n; ++i) g.Kp[i] = 0.1;  // K_pv = diag(0.2, 0.2, 0.2, 0.1, 0.1)
  return g;
}

}  // namespace

const char* control_law_name(ControlLaw law) { return law == ControlLaw::Thesis ? "thesis" : "tool"; }

std::optional<ControlLaw> control_law_named(std::string_view name) {
  if (name == "thesis") return ControlLaw::Thesis;
  if (name == "tool") return ControlLaw::Tool;
  return std::nullopt;
}

TeleoperationGains thesis_holonomic_gains(int n) {
  TeleoperationGains g;
  g.master = uniform(n, 0.055, 0.0055, 10.05, 0.25, 0.01, 0.015);  // section 4.3
  g.virt = thesis_virtual(n, 0.2);
  return g;
}

TeleoperationGains thesis_nonholonomic_gains(int n) {
  TeleoperationGains g;
  g.master = uniform(n, 0.055, 0.055, 0.01, 0.25, 0.01, 0.015);  // section 4.4
  g.virt = thesis_virtual(n, 2.0);
  return g;
}

}  // namespace needle::haptics
