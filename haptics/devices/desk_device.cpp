#include "haptics/devices/desk_device.hpp"

#include <algorithm>
#include <cmath>

namespace needle::haptics {
namespace {

double clamp_finite(double value, double lo, double hi, double otherwise) {
  return std::isfinite(value) ? std::clamp(value, lo, hi) : otherwise;
}

}  // namespace

DeskPose DeskWorkspace::centre() const noexcept {
  DeskPose pose;
  for (int i = 0; i < 3; ++i) pose.position_m[i] = 0.5 * (min_m[i] + max_m[i]);
  return pose;
}

DeskPose DeskWorkspace::clamp(const DeskPose& pose) const noexcept {
  const DeskPose middle = centre();
  DeskPose out;
  for (int i = 0; i < 3; ++i)
    out.position_m[i] = clamp_finite(pose.position_m[i], min_m[i], max_m[i], middle.position_m[i]);
  out.wrist_rad[0] = clamp_finite(pose.wrist_rad[0], -swing_limit_rad, swing_limit_rad, 0.0);
  out.wrist_rad[1] = clamp_finite(pose.wrist_rad[1], -tilt_limit_rad, tilt_limit_rad, 0.0);
  return out;
}

DeskDevice::DeskDevice(const DeviceSpec& spec, const DeskWorkspace& workspace) : spec_(spec), workspace_(workspace) {
  if (!spec.desk()) throw DeviceError("device " + spec.text() + ": not a desk device (mouse, keyboard, gamepad[:N])");
  caps_.name = spec.text();
  caps_.command_space = CommandSpace::kNone;
  caps_.joint_count = 2;  // the virtual wrist
  for (int i = 0; i < 3; ++i) {
    caps_.workspace_min_m[i] = workspace.min_m[i];
    caps_.workspace_max_m[i] = workspace.max_m[i];
  }
  writer_copy_.pose = workspace.centre();
  input_.store(writer_copy_);
}

void DeskDevice::set_pose(const DeskPose& pose) noexcept {
  writer_copy_.pose = workspace_.clamp(pose);
  input_.store(writer_copy_);
}

void DeskDevice::set_buttons(uint32_t buttons) noexcept {
  writer_copy_.buttons = buttons;
  input_.store(writer_copy_);
}

void DeskDevice::set_connected(bool connected) noexcept {
  writer_copy_.connected = connected ? 1 : 0;
  input_.store(writer_copy_);
}

void DeskDevice::read(DeviceReading& out) noexcept {
  const Input in = input_.load();
  out.sequence = ++sequence_;  // sampled every tick: always fresh
  out.connected = in.connected;
  out.joint_count = 2;
  out.buttons = in.buttons;
  for (int i = 0; i < 3; ++i) out.position_m[i] = in.pose.position_m[i];
  out.joint_rad[0] = in.pose.wrist_rad[0];
  out.joint_rad[1] = in.pose.wrist_rad[1];
}

}  // namespace needle::haptics
