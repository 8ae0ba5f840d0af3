// A trainee's plans for the penetrable-sphere task and the layered target (assets/tasks/) on a desk
// device, in the device's own terms: where its handle and wrist go and how fast. The app's tests
// play it through the keyboard and mouse mappings; the command-line tests through xdotool.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "app/desk_input.hpp"
#include "app/session_rig.hpp"
#include "engine/scene.hpp"
#include "engine/screen_projection.hpp"
#include "haptics/devices/desk_mapping.hpp"
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
inline void wrist_for(const Eigen::Matrix3d& device_to_scene, const Eigen::Vector3d& start,
                      const Eigen::Vector3d& wanted, double& swing, double& tilt) {
  const Eigen::Vector3d away = device_to_scene.col(1).cross(device_to_scene.col(0)).normalized();
  tilt = std::acos(wanted.normalized().dot(away)) - std::acos(start.normalized().dot(away));
  const Eigen::Vector3d p0 = start - start.dot(away) * away, p = wanted - wanted.dot(away) * away;
  swing = std::atan2(p0.cross(p).dot(away), p0.dot(p));
}

// Where the tool starts (world frame) and the view's axes, from a rig built for planning: what the
// app starts its desk input with (app::DeskInput::start_at).
using DeskStart = app::ToolStart;

inline DeskStart desk_start(app::SessionRig& rig) { return *rig.tool_start(); }

// The start of the rig `needle-sim run --device DEVICE` builds for `task_file` (its files in `dir`).
inline DeskStart desk_start(const std::filesystem::path& task_file, const std::string& device,
                            const std::filesystem::path& dir) {
  const training::Task task = training::load_task(task_file);
  app::RigOptions options;
  options.device = haptics::DeviceSpec::parse(device);
  options.camera = engine::load_scene(task.scene).camera;
  options.out_dir = dir;
  app::SessionRig rig(task, options);
  return desk_start(rig);
}

// A task's marker by name (std::logic_error when it has none) and its point or axis origin and direction.
inline const training::Marker& plan_marker(const training::Task& task, const char* name) {
  for (const training::Marker& m : task.markers)
    if (m.name == name) return m;
  throw std::logic_error(std::string("no marker ") + name);
}
inline Eigen::Vector3d marker_point(const training::Task& task, const char* name) {
  const training::Marker& m = plan_marker(task, name);
  return {m.position[0], m.position[1], m.position[2]};
}
inline Eigen::Vector3d marker_direction(const training::Task& task, const char* name) {
  const training::Marker& m = plan_marker(task, name);
  return {m.direction[0], m.direction[1], m.direction[2]};
}

// The handle's position (device frame) that puts the tip at `tip` (world), the handle having
// started at `device_start` with the tip at start.tip.
inline Eigen::Vector3d device_for(const DeskStart& start, const Eigen::Vector3d& device_start,
                                  const Eigen::Vector3d& tip) {
  return device_start + start.device_to_scene.transpose() * (tip - start.tip);
}

// Come to 15 mm above the entry and turn onto the insertion axis; insert 3 cm along the axis;
// pivot 45° to vertical about the tip; advance 2 cm to the target; withdraw 8.5 cm straight up.
// The handle starts at `device_start`, the wrist at zero.
inline std::vector<DeskWaypoint> penetrable_plan(const training::Task& task, const DeskStart& start,
                                                 const Eigen::Vector3d& device_start) {
  const Eigen::Vector3d entry = marker_point(task, "insertion_axis"), axis = marker_direction(task, "insertion_axis");
  const Eigen::Vector3d down = marker_direction(task, "pivot_axis"), target = marker_point(task, "target");
  auto device = [&](const Eigen::Vector3d& tip) { return device_for(start, device_start, tip); };
  double swing_in = 0, tilt_in = 0, swing_down = 0, tilt_down = 0;
  wrist_for(start.device_to_scene, start.direction, axis, swing_in, tilt_in);
  wrist_for(start.device_to_scene, start.direction, down, swing_down, tilt_down);
  const Eigen::Vector3d inserted = entry + 0.03 * axis;
  return {
      {device(entry - 0.015 * axis), 0.0, 0.0, 3.0},                // above the entry
      {device(entry - 0.015 * axis), swing_in, tilt_in, 2.0},       // turned onto the axis
      {device(inserted), swing_in, tilt_in, 6.0},                   // insert 3 cm (4.5 cm of travel)
      {device(inserted), swing_in, tilt_in, 1.5},                   // hold the depth
      {device(inserted), swing_down, tilt_down, 4.0},               // pivot about the tip
      {device(inserted), swing_down, tilt_down, 1.5},               // hold it vertical
      {device(target), swing_down, tilt_down, 3.0},                 // advance to the target
      {device(target), swing_down, tilt_down, 1.5},                 // hold there
      {device(target - 0.085 * down), swing_down, tilt_down, 4.0},  // withdraw
      {device(target - 0.085 * down), swing_down, tilt_down, 1.0},
  };
}

// The layered target (assets/tasks/layered_target.json): come to 15 mm above the entry and turn
// onto the planned axis; insert slowly through skin, fat and muscle with the handle to `depth_m`
// along it; hold 2.5 s (the step holds 1.5 s in its 31 to 38 mm band); withdraw 4 cm above the
// entry. The tip lags the handle by the tissue's resistance over the coupling's stiffness (about
// 1 N in the muscle: 3.4 mm, measured with the mouse at 34 mm), so the handle
// goes 37 mm deep and the tip stops 33.0 mm deep (DeskSessions.LayeredTargetWithTheMouse).
inline std::vector<DeskWaypoint> layered_target_plan(const training::Task& task, const DeskStart& start,
                                                     const Eigen::Vector3d& device_start, double depth_m = 0.037) {
  const Eigen::Vector3d entry = marker_point(task, "planned_axis"), axis = marker_direction(task, "planned_axis");
  auto device = [&](const Eigen::Vector3d& tip) { return device_for(start, device_start, tip); };
  double swing = 0, tilt = 0;
  wrist_for(start.device_to_scene, start.direction, axis, swing, tilt);
  return {
      {device(entry - 0.015 * axis), 0.0, 0.0, 3.0},        // above the entry
      {device(entry - 0.015 * axis), swing, tilt, 2.0},     // turned onto the axis
      {device(entry + depth_m * axis), swing, tilt, 10.0},  // insert (5.2 cm of travel, 5 mm/s)
      {device(entry + depth_m * axis), swing, tilt, 2.5},   // hold at the target
      {device(entry - 0.04 * axis), swing, tilt, 6.0},      // withdraw
      {device(entry - 0.04 * axis), swing, tilt, 1.0},
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

// Where the app puts the mouse's cursor when a session of `task` starts in a window of `extent`
// (on the tool's start), in half window heights from the centre, x right, y up.
inline Eigen::Vector2d mouse_cursor_start(const training::Task& task, const DeskStart& start, engine::Extent extent) {
  const std::optional<glm::vec2> px = engine::project_to_screen(engine::load_scene(task.scene).camera, extent,
                                                                glm::vec3(start.tip.x(), start.tip.y(), start.tip.z()));
  if (!px) throw std::logic_error("the tool's start is not in the view");
  const double half = 0.5 * extent.height;
  return {(px->x - 0.5 * extent.width) / half, (half - px->y) / half};
}

// One input of a mouse playing a plan: where the cursor goes (half window heights), whether the
// right button goes down before the move or up instead of it, and the wheel's notches after it
// (in along the needle positive; the app then puts the cursor on the handle, `after_wheel`).
struct MouseInput {
  Eigen::Vector2d cursor;
  bool press = false, release = false;
  double notches = 0.0;
  Eigen::Vector2d after_wheel = Eigen::Vector2d::Zero();
};

// Where the handle starts for a mouse whose cursor the app put at `cursor` (half heights) in `view`.
inline Eigen::Vector3d mouse_device_start(const haptics::MouseView& view, const Eigen::Vector2d& cursor) {
  haptics::MouseMapping mouse({}, view);
  mouse.pointer(cursor.x(), cursor.y(), false);
  return {mouse.pose().position_m[0], mouse.pose().position_m[1], mouse.pose().position_m[2]};
}

// A trainee's mouse playing a plan as the app reads it (app/desk_input.cpp): the right button held
// turns the wrist (and once it is released the cursor is back where it went down), else the cursor
// puts the handle under it (through `view`) and the wheel pushes it along the needle a notch at a
// time, where the needle's depth changes (after which the app puts the cursor on the handle). It
// keeps its own MouseMapping, fed as the app feeds it, to know what is left to do. `pixel`: the
// cursor's resolution in half heights (0: exact); a turn or move under half of it is not made.
class MousePlayer {
 public:
  MousePlayer(std::vector<DeskWaypoint> plan, const DeskStart& start, const haptics::MouseView& view,
              const Eigen::Vector2d& cursor, double pixel = 0.0)
      : plan_(std::move(plan)),
        start_(start),
        device_start_(mouse_device_start(view, cursor)),
        cursor_(cursor),
        pixel_(pixel),
        mouse_({}, view),
        lowest_(cursor),
        highest_(cursor) {
    mouse_.pointer(cursor_.x(), cursor_.y(), false);
  }

  // The input for `t` seconds into the plan; `axis`: the needle's axis now (world frame), which the
  // app pushes along once it has a state (a script made beforehand has none: the wrist's direction).
  MouseInput step(double t, const std::optional<std::array<double, 3>>& axis = std::nullopt) {
    const DeskWaypoint want = plan_at(plan_, device_start_, t);
    const haptics::DeskPose& pose = mouse_.pose();
    const Eigen::Vector2d turn(want.swing_rad - pose.wrist_rad[0], want.tilt_rad - pose.wrist_rad[1]);
    const double least_turn = std::max(1e-4, 0.5 * pixel_ * haptics::MouseMapping::kRadPerHalfHeight);
    const bool turning = std::abs(turn.x()) > least_turn || std::abs(turn.y()) > least_turn;
    MouseInput input;
    if (!turning && turning_) {  // the button goes up; the app puts the cursor back where it went down
      turning_ = false;
      cursor_ = pressed_;
      mouse_.pointer(cursor_.x(), cursor_.y(), false);
      input.cursor = cursor_;
      input.release = true;
      return input;
    }
    if (turning && !turning_) {  // the button goes down where the cursor is
      input.press = true;
      turning_ = true;
      pressed_ = cursor_;
      mouse_.pointer(cursor_.x(), cursor_.y(), true);
    }
    const haptics::NeedleDirection direction =
        axis ? app::needle_direction(start_, *axis) : app::needle_direction(start_, pose);
    mouse_.set_needle_direction(direction);
    if (turning) {
      cursor_ += turn / haptics::MouseMapping::kRadPerHalfHeight;
    } else {
      // The wheel for the depth the needle's direction can give (a needle in the screen's plane has
      // none: the cursor does it all), the cursor for the rest, where it must be before the wheel.
      const double* d = direction.device;
      if (std::abs(d[2]) > 0.2)
        input.notches =
            std::round((want.device_m.z() - pose.position_m[2]) / (d[2] * haptics::MouseMapping::kDepthPerNotch_m));
      const double pushed = input.notches * haptics::MouseMapping::kDepthPerNotch_m;
      double x = 0.0, y = 0.0;
      mouse_.cursor_for(want.device_m.x() - pushed * d[0], want.device_m.y() - pushed * d[1], x, y);
      cursor_ = Eigen::Vector2d(x, y);
    }
    if (pixel_ > 0) cursor_ = (cursor_ / pixel_).array().round().matrix() * pixel_;
    lowest_ = lowest_.cwiseMin(cursor_);
    highest_ = highest_.cwiseMax(cursor_);
    mouse_.pointer(cursor_.x(), cursor_.y(), turning);
    input.cursor = cursor_;
    if (input.notches != 0.0) {  // the app puts the cursor on the handle after the wheel
      mouse_.scroll(input.notches);
      double x = 0.0, y = 0.0;
      mouse_.cursor_at_handle(x, y);
      cursor_ = Eigen::Vector2d(x, y);
      if (pixel_ > 0) cursor_ = (cursor_ / pixel_).array().round().matrix() * pixel_;
      mouse_.pointer(cursor_.x(), cursor_.y(), false);
      input.after_wheel = cursor_;
    }
    return input;
  }
  const Eigen::Vector3d& device_start() const { return device_start_; }

  const haptics::DeskPose& pose() const { return mouse_.pose(); }
  // How far the cursor went, in half heights.
  const Eigen::Vector2d& lowest() const { return lowest_; }
  const Eigen::Vector2d& highest() const { return highest_; }

 private:
  std::vector<DeskWaypoint> plan_;
  DeskStart start_;
  Eigen::Vector3d device_start_;
  Eigen::Vector2d cursor_, pressed_ = Eigen::Vector2d::Zero();
  double pixel_;
  haptics::MouseMapping mouse_;
  bool turning_ = false;
  Eigen::Vector2d lowest_, highest_;
};

}  // namespace needle::test
