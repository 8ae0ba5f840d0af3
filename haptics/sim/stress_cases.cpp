#include "haptics/sim/stress_cases.hpp"

#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "haptics/model/kinematics.hpp"

namespace needle::haptics {
namespace {

std::string number(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", v);
  return text;
}

void scale(RobotGains& g, double k) {
  g.Ka *= k;
  g.Kp *= k;
  g.Kf *= k;
}

}  // namespace

double passivity_stiffness_bound(const Scenario& s) { return 2.0 * (s.hand.damping_Ns_per_m - 0.0) / s.period_s; }

Scenario with_gain_scale(Scenario s, double k) {
  scale(s.gains.master, k);
  scale(s.gains.virt, k);
  return s;
}

Scenario with_period_scale(Scenario s, double k) {
  s.period_s *= k;
  return s;
}

Scenario holding_pose(Scenario s, const VecN& q0, bool in_tissue) {
  // The hand holds the tip where q0 puts it, then moves it 1 cm along the needle and back.
  const Eigen::Isometry3d tip = tip_pose(s.master, q0);
  const Eigen::Vector3d axis = tip.linear().col(0);
  s.q0 = q0;
  s.trajectory = HandTrajectory({{0.0, tip.translation(), axis},
                                 {2.0, tip.translation(), axis},
                                 {4.0, tip.translation() + 0.01 * axis, axis},
                                 {6.0, tip.translation(), axis}});
  s.scene = Scene{};
  if (in_tissue) {
    const SurfacePrimitive sphere = SurfacePrimitive::sphere(tip.translation(), 0.05);
    s.scene.tissue = TissueModel::single_surface(LayerShape::of_surface({&sphere, 1}, ImplicitSurface::Combine::Union));
  }
  s.duration_s = 8.0;
  return s;
}

Scenario pressing(Scenario s, double force_N, double hold_until_s) {
  // Approach the sphere's contact point of the holonomic scenario, then hold the hand a spring
  // stretch of force_N / K_h inside the surface.
  const Eigen::Vector3d start = s.trajectory.at(0.0).position, dir0 = s.trajectory.at(0.0).direction;
  const HandTarget press_target = s.trajectory.at(8.0);  // on the surface, pressing lightly
  const SurfaceSample at = s.scene.rigid.evaluate(press_target.position);
  const Eigen::Vector3d surface_point = press_target.position - at.phi * at.gradient;
  const Eigen::Vector3d deep = surface_point - force_N / s.hand.stiffness_N_per_m * at.gradient;
  s.trajectory = HandTrajectory({{0.0, start, dir0},
                                 {4.0, surface_point + 0.02 * at.gradient, -at.gradient},
                                 {8.0, deep, -at.gradient},
                                 {hold_until_s, deep, -at.gradient}});
  s.duration_s = hold_until_s + 2.0;
  return s;
}

Scenario with_layer_mechanics(Scenario s, void (*change)(LayerMechanics&, double), double k) {
  const TissueModel& tissue = s.scene.tissue;
  std::vector<TissueLayer> layers(tissue.layers().begin(), tissue.layers().end());
  for (TissueLayer& layer : layers)
    if (!layer.mechanics.rigid) change(layer.mechanics, k);
  s.scene.tissue = TissueModel(std::move(layers), tissue.stick());
  return s;
}

Scenario pushing_onto_bone(Scenario s, double force_N) {
  if (s.trajectory.waypoints().size() < 3)
    throw std::invalid_argument(s.name + ": the push needs the script's first three waypoints");
  std::vector<HandWaypoint> waypoints(s.trajectory.waypoints().begin(), s.trajectory.waypoints().begin() + 3);
  const HandWaypoint on_surface = waypoints.back();
  // March along the needle to the first rigid layer (0.1 mm steps, at most 0.3 m).
  double depth = 0.0;
  for (; depth < 0.3; depth += 1e-4) {
    const int layer = s.scene.tissue.layer_at(on_surface.position + depth * on_surface.direction);
    if (layer >= 0 && s.scene.tissue.layer(layer).mechanics.rigid) break;
  }
  if (depth >= 0.3) throw std::invalid_argument(s.name + ": no rigid layer on the needle's line");
  const Eigen::Vector3d deep =
      on_surface.position + (depth + force_N / s.hand.stiffness_N_per_m) * on_surface.direction;
  waypoints.push_back({on_surface.t + 15.0, deep, on_surface.direction});
  waypoints.push_back({on_surface.t + 20.0, deep, on_surface.direction});
  waypoints.push_back({on_surface.t + 30.0, on_surface.position, on_surface.direction});
  s.trajectory = HandTrajectory(waypoints);
  s.duration_s = on_surface.t + 32.0;
  return s;
}

std::vector<StressCase> layered_stress_cases(const Scenario& s) {
  std::vector<StressCase> cases;
  const std::string of = " (" + s.name + ")";
  for (double k : {0.1, 0.3, 1.0, 3.0, 10.0}) {
    cases.push_back({"puncture force x" + of, number(k),
                     with_layer_mechanics(
                         s, [](LayerMechanics& m, double k) { m.puncture_force_N *= k; }, k)});
    cases.push_back({"friction x" + of, number(k),
                     with_layer_mechanics(
                         s,
                         [](LayerMechanics& m, double k) {
                           m.friction_N_per_m *= k;
                           m.static_friction_N_per_m *= k;
                         },
                         k)});
    cases.push_back({"stiffness x" + of, number(k),
                     with_layer_mechanics(
                         s,
                         [](LayerMechanics& m, double k) {
                           m.stiffness_N_per_m *= k;
                           m.stiffness2_N_per_m2 *= k;
                         },
                         k)});
  }
  for (double k : {1.0, 2.0, 4.0, 8.0}) cases.push_back({"period x" + of, number(k), with_period_scale(s, k)});
  bool bone = false;
  for (const TissueLayer& layer : s.scene.tissue.layers()) bone = bone || layer.mechanics.rigid;
  if (bone) {
    const double force = 2 * s.device.force_limit_N;
    cases.push_back({"push onto bone" + of, number(force) + " N (2x limit)", pushing_onto_bone(s, force)});
  }
  return cases;
}

std::vector<StressCase> stress_cases(const Scenario& h, const Scenario& nh, double sustained_s) {
  std::vector<StressCase> cases;
  for (const Scenario* base : {&h, &nh}) {
    for (double k : {0.1, 0.3, 1.0, 3.0, 10.0, 30.0, 100.0})
      cases.push_back({"gains x (" + base->name + ")", number(k), with_gain_scale(*base, k)});
    for (double k : {1.0, 2.0, 4.0, 8.0})
      cases.push_back({"period x (" + base->name + ")", number(k), with_period_scale(*base, k)});
  }
  cases.push_back(
      {"singular pose", "arm stretched", holding_pose(nh, (VecN(5) << 0.0, 0.0, 0.0, 0.0, 0.5).finished(), false)});
  cases.push_back({"singular pose", "wrist roll along needle, in tissue",
                   holding_pose(nh, (VecN(5) << 0.0, 1.0, -1.6, 0.0, 0.0).finished(), true)});
  const double limit = h.device.force_limit_N;
  cases.push_back({"operator push", number(2 * limit) + " N (2x limit)", pressing(h, 2 * limit, 20.0)});
  cases.push_back({"sustained contact", number(sustained_s) + " s at 1 N", pressing(h, 1.0, sustained_s)});
  const double k_crit = passivity_stiffness_bound(h);
  for (double k : {0.1, 0.3, 1.0, 3.0, 10.0}) {
    Scenario s = pressing(h, 1.0, 14.0);
    // Stiffness α ω² = k K_crit; ξω kept, so the penalty damping 2αξω stays the thesis's.
    const double xi_omega = s.gains.gpm.xi * s.gains.gpm.omega;
    s.gains.gpm.omega = std::sqrt(k * k_crit / s.gains.gpm.alpha);
    s.gains.gpm.xi = xi_omega / s.gains.gpm.omega;
    cases.push_back({"penalty stiffness x K_crit", number(k) + " (" + number(k * k_crit) + " N/m)", s});
  }
  return cases;
}

}  // namespace needle::haptics
