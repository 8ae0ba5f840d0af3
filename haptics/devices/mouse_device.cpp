#include "haptics/devices/mouse_device.hpp"

#include <algorithm>

namespace needle::haptics {

MouseDevice::MouseDevice(const MouseMapping& mapping) : mapping_(mapping) {
  caps_.name = "mouse";
  caps_.command_space = CommandSpace::kNone;
  for (int i = 0; i < 3; ++i) {
    caps_.workspace_min_m[i] = mapping.workspace_min_m[i];
    caps_.workspace_max_m[i] = mapping.workspace_max_m[i];
  }
}

void MouseDevice::set_pointer(double x_norm, double y_norm) noexcept {
  writer_copy_.x_norm = std::clamp(x_norm, -1.0, 1.0);
  writer_copy_.y_norm = std::clamp(y_norm, -1.0, 1.0);
  input_.store(writer_copy_);
}

void MouseDevice::add_depth_steps(double steps) noexcept {
  // Clamp the step count so scrolling past the end does not build up a dead zone.
  const double centre = 0.5 * (mapping_.workspace_min_m[2] + mapping_.workspace_max_m[2]);
  const double max_steps = (mapping_.workspace_max_m[2] - centre) / mapping_.depth_per_step_m;
  writer_copy_.depth_steps = std::clamp(writer_copy_.depth_steps + steps, -max_steps, max_steps);
  input_.store(writer_copy_);
}

void MouseDevice::set_buttons(uint32_t buttons) noexcept {
  writer_copy_.buttons = buttons;
  input_.store(writer_copy_);
}

void MouseDevice::read(DeviceReading& out) noexcept {
  const Input in = input_.load();
  const double* lo = mapping_.workspace_min_m;
  const double* hi = mapping_.workspace_max_m;
  out.sequence = ++sequence_;  // sampled every tick: always fresh
  out.connected = 1;
  out.joint_count = 0;
  out.buttons = in.buttons;
  out.position_m[0] = lo[0] + 0.5 * (in.x_norm + 1.0) * (hi[0] - lo[0]);
  out.position_m[1] = lo[1] + 0.5 * (in.y_norm + 1.0) * (hi[1] - lo[1]);
  out.position_m[2] = 0.5 * (lo[2] + hi[2]) + in.depth_steps * mapping_.depth_per_step_m;
}

}  // namespace needle::haptics
