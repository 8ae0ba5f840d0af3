// A trainee's plan for the penetrable-sphere task (assets/tasks/penetrable_sphere.json) on a desk
// device, in the device's own terms: where its handle and wrist go and how fast. The app's tests
// play it through the keyboard and mouse mappings; the command-line tests through xdotool.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cmath>
#include <vector>

#include "app/session_rig.hpp"
#include "haptics/realtime/task_space_step.hpp"
#include "training/tasks/task.hpp"

namespace needle::test {

// The handle at `device_m` (device frame) and the wrist at (swing, tilt), reached in a straight
// line over `seconds` from the waypoint before.
struct DeskWaypoint {
  Eigen::Vector3d device_m;
  double swing_rad = 0.0, tilt_rad = 0.0;
  double seconds = 0.0;
};

// The wrist angles that turn `start` onto `wanted` (the inverse of haptics::wrist_direction, away
// from its poles): the tilt changes the angle to the view's axis, the swing turns about it.
inline void wrist_for(const Eigen::Matrix3d& device_to_scene, const Eigen::Vector3d& start, const Eigen::Vector3d& wanted,
                      double& swing, double& tilt) {
  const Eigen::Vector3d away = device_to_scene.col(1).cross(device_to_scene.col(0)).normalized();
  tilt = std::acos(wanted.normalized().dot(away)) - std::acos(start.normalized().dot(away));
  const Eigen::Vector3d p0 = start - start.dot(away) * away, p = wanted - wanted.dot(away) * away;
  swing = std::atan2(p0.cross(p).dot(away), p0.dot(p));
}

// Where the tool starts (world frame) and the view's axes, from a rig built for planning.
struct DeskStart {
  Eigen::Vector3d tip, direction;
  Eigen::Matrix3d device_to_scene;
};

inline DeskStart desk_start(app::SessionRig& rig) {
  auto& step = dynamic_cast<haptics::TaskSpaceStep&>(rig.step());
  haptics::DeviceReading reading;
  rig.device().read(reading);
  haptics::DeviceCommand command;
  haptics::ToolSnapshot state;
  step.step(reading, 0.001, command, state);
  DeskStart start;
  start.tip = Eigen::Vector3d(state.needle_tip_m[0], state.needle_tip_m[1], state.needle_tip_m[2]);
  start.direction = Eigen::Vector3d(haptics::needle_axis(state).data());
  start.device_to_scene = step.coupling().device_to_scene;
  return start;
}

// Come to 15 mm above the entry and turn onto the insertion axis; insert 3 cm along the axis;
// pivot 45° to vertical about the tip; advance 2 cm to the target; withdraw 8.5 cm straight up.
// The handle starts at `device_start`, the wrist at zero.
inline std::vector<DeskWaypoint> penetrable_plan(const training::Task& task, const DeskStart& start,
                                                 const Eigen::Vector3d& device_start) {
  auto marker = [&task](const char* name) -> const training::Marker& {
    for (const training::Marker& m : task.markers)
      if (m.name == name) return m;
    throw std::logic_error(std::string("no marker ") + name);
  };
  const training::Marker& insertion = marker("insertion_axis");
  const training::Marker& pivot = marker("pivot_axis");
  const Eigen::Vector3d entry(insertion.position[0], insertion.position[1], insertion.position[2]);
  const Eigen::Vector3d axis(insertion.direction[0], insertion.direction[1], insertion.direction[2]);
  const Eigen::Vector3d down(pivot.direction[0], pivot.direction[1], pivot.direction[2]);
  const training::Marker& target_marker = marker("target");
  const Eigen::Vector3d target(target_marker.position[0], target_marker.position[1], target_marker.position[2]);
  auto device = [&](const Eigen::Vector3d& tip) -> Eigen::Vector3d {
    return device_start + start.device_to_scene.transpose() * (tip - start.tip);
  };
  double swing_in = 0, tilt_in = 0, swing_down = 0, tilt_down = 0;
  wrist_for(start.device_to_scene, start.direction, axis, swing_in, tilt_in);
  wrist_for(start.device_to_scene, start.direction, down, swing_down, tilt_down);
  const Eigen::Vector3d inserted = entry + 0.03 * axis;
  return {
      {device(entry - 0.015 * axis), 0.0, 0.0, 3.0},              // above the entry
      {device(entry - 0.015 * axis), swing_in, tilt_in, 2.0},     // turned onto the axis
      {device(inserted), swing_in, tilt_in, 6.0},                 // insert 3 cm (4.5 cm of travel)
      {device(inserted), swing_in, tilt_in, 1.5},                 // hold the depth
      {device(inserted), swing_down, tilt_down, 4.0},             // pivot about the tip
      {device(inserted), swing_down, tilt_down, 1.5},             // hold it vertical
      {device(target), swing_down, tilt_down, 3.0},               // advance to the target
      {device(target), swing_down, tilt_down, 1.5},               // hold there
      {device(target - 0.085 * down), swing_down, tilt_down, 4.0},  // withdraw
      {device(target - 0.085 * down), swing_down, tilt_down, 1.0},
  };
}

// The plan's pose at `t` seconds (the last one after its end).
inline DeskWaypoint plan_at(const std::vector<DeskWaypoint>& plan, const Eigen::Vector3d& device_start, double t) {
  DeskWaypoint from{device_start, 0.0, 0.0, 0.0};
  for (const DeskWaypoint& to : plan) {
    if (t <= to.seconds) {
      const double u = to.seconds > 0 ? t / to.seconds : 1.0;
      return {from.device_m + u * (to.device_m - from.device_m), from.swing_rad + u * (to.swing_rad - from.swing_rad),
              from.tilt_rad + u * (to.tilt_rad - from.tilt_rad), 0.0};
    }
    t -= to.seconds;
    from = to;
  }
  return from;
}

inline double plan_seconds(const std::vector<DeskWaypoint>& plan) {
  double total = 0.0;
  for (const DeskWaypoint& w : plan) total += w.seconds;
  return total;
}

}  // namespace needle::test
