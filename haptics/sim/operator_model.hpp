// The operator: a hand impedance (mass, damping, stiffness) tracking a scripted trajectory of the
// stylus tip and of the stylus direction. Default values are one subject's identified 3-D arm
// dynamics: M = 0.554 kg, B = 6.45 N·s/m, K = 135 N/m (van Beek, Bergmann Tiest, Mugge, Kappers,
// "Haptic perception of force magnitude and its relation to postural arm dynamics in 3D",
// Scientific Reports 5:18004, 2015, Fig. 3). The stylus direction is held by the same tissue over a
// grip length d (a two-point pen grip): rotational stiffness K d², damping B d², inertia M d².
#pragma once

#include <Eigen/Geometry>
#include <vector>

#include "haptics/control/teleoperation.hpp"

namespace needle::haptics {

struct HandImpedance {
  double mass_kg = 0.554;
  double damping_Ns_per_m = 6.45;
  double stiffness_N_per_m = 135.0;
  double grip_length_m = 0.05;  // design value: thumb-to-finger spacing on the stylus
  double rotational_stiffness() const { return stiffness_N_per_m * grip_length_m * grip_length_m; }
  double rotational_damping() const { return damping_Ns_per_m * grip_length_m * grip_length_m; }
  double rotational_inertia() const { return mass_kg * grip_length_m * grip_length_m; }
};

struct HandWaypoint {
  double t = 0.0;
  Eigen::Vector3d position = Eigen::Vector3d::Zero();    // tip, robot base frame
  Eigen::Vector3d direction = Eigen::Vector3d::UnitX();  // stylus axis x₅, unit
};

struct HandTarget {
  Eigen::Vector3d position, velocity, direction, omega;
};

// Minimum-jerk blends between consecutive waypoints (position and direction, the latter along
// the great circle); holds the last waypoint afterwards. at() does not allocate.
class HandTrajectory {
 public:
  HandTrajectory() = default;
  explicit HandTrajectory(std::vector<HandWaypoint> waypoints);  // throws unless t strictly increases
  HandTarget at(double t) const;
  // The same waypoints shifted in time so that the first is at t0, and the first `anchored` moved to
  // (position, direction): a reaction's relative waypoints started where the hand is when it begins.
  // Allocates nothing.
  void restart(double t0, const Eigen::Vector3d& position, const Eigen::Vector3d& direction, int anchored = 1) noexcept;
  double end_time() const { return waypoints_.empty() ? 0.0 : waypoints_.back().t; }
  const std::vector<HandWaypoint>& waypoints() const { return waypoints_; }

 private:
  std::vector<HandWaypoint> waypoints_;
};

// Spring-damper part of the hand's wrench on the tip (its inertia is carried by the plant).
Wrench hand_impedance_wrench(const HandImpedance& hand, const HandTarget& target, const Eigen::Isometry3d& tip,
                             const Eigen::Matrix<double, 6, 1>& tip_twist);

}  // namespace needle::haptics
