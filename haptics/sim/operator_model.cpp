#include "haptics/sim/operator_model.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace needle::haptics {

HandTrajectory::HandTrajectory(std::vector<HandWaypoint> waypoints) : waypoints_(std::move(waypoints)) {
  if (waypoints_.empty()) throw std::invalid_argument("hand trajectory needs at least one waypoint");
  for (size_t i = 0; i < waypoints_.size(); ++i) {
    if (!(waypoints_[i].direction.norm() > 1e-9))
      throw std::invalid_argument("waypoint " + std::to_string(i) + ": direction must be nonzero");
    waypoints_[i].direction.normalize();
    if (i > 0 && !(waypoints_[i].t > waypoints_[i - 1].t))
      throw std::invalid_argument("waypoint " + std::to_string(i) + ": times must strictly increase");
  }
}

HandTarget HandTrajectory::at(double t) const {
  // The last waypoint at or before t (the first when t precedes it), by bisection: a script may hold
  // as many waypoints as a 16 MiB file does, and this runs every tick.
  const auto after = std::upper_bound(waypoints_.begin() + 1, waypoints_.end(), t,
                                      [](double time, const HandWaypoint& w) { return time < w.t; });
  const size_t i = size_t(after - waypoints_.begin()) - 1;
  const HandWaypoint& a = waypoints_[i];
  HandTarget out{a.position, Eigen::Vector3d::Zero(), a.direction, Eigen::Vector3d::Zero()};
  if (i + 1 == waypoints_.size() || t <= a.t) return out;
  const HandWaypoint& b = waypoints_[i + 1];
  const double span = b.t - a.t, u = (t - a.t) / span;
  const double s = u * u * u * (10 - 15 * u + 6 * u * u);  // minimum jerk
  const double s_dot = 30 * u * u * (1 - u) * (1 - u) / span;
  out.position = a.position + s * (b.position - a.position);
  out.velocity = s_dot * (b.position - a.position);
  const Eigen::Vector3d axis = a.direction.cross(b.direction);
  const double angle = std::atan2(axis.norm(), a.direction.dot(b.direction));
  if (angle > 1e-12) {
    const Eigen::Vector3d unit = axis.normalized();
    out.direction = Eigen::AngleAxisd(s * angle, unit) * a.direction;
    out.omega = s_dot * angle * unit;
  }
  return out;
}

void HandTrajectory::restart(double t0, const Eigen::Vector3d& position, const Eigen::Vector3d& direction,
                             int anchored) noexcept {
  if (waypoints_.empty()) return;
  const double shift = t0 - waypoints_.front().t;
  for (HandWaypoint& w : waypoints_) w.t += shift;
  for (int k = 0; k < anchored && size_t(k) < waypoints_.size(); ++k) {
    waypoints_[size_t(k)].position = position;
    if (direction.norm() > 1e-9) waypoints_[size_t(k)].direction = direction.normalized();
  }
}

Wrench hand_impedance_wrench(const HandImpedance& hand, const HandTarget& target, const Eigen::Isometry3d& tip,
                             const Eigen::Matrix<double, 6, 1>& tip_twist) {
  Wrench w;
  w.head<3>() = hand.stiffness_N_per_m * (target.position - tip.translation()) +
                hand.damping_Ns_per_m * (target.velocity - tip_twist.head<3>());
  // Turns the stylus axis x₅ toward the target direction (small-angle spring on sin θ).
  w.tail<3>() = hand.rotational_stiffness() * tip.linear().col(0).cross(target.direction) +
                hand.rotational_damping() * (target.omega - tip_twist.tail<3>());
  return w;
}

}  // namespace needle::haptics
