#include "haptics/devices/desk_mapping.hpp"

#include <algorithm>
#include <cmath>

namespace needle::haptics {
namespace {

double finite_or_zero(double v) { return std::isfinite(v) ? v : 0.0; }

// The handle moved `metres` along the needle.
void along(DeskPose& pose, const NeedleDirection& d, double metres) noexcept {
  for (int i = 0; i < 3; ++i) pose.position_m[i] += metres * d.device[i];
}

}  // namespace

MouseMapping::MouseMapping(const DeskWorkspace& workspace, const MouseView& view)
    : workspace_(workspace), view_(view), pose_(workspace.centre()) {}

void MouseMapping::cursor_for(double x_m, double y_m, double& x, double& y) const noexcept {
  const DeskPose middle = workspace_.centre();
  const double scale = view_.metres_per_half_height(pose_.position_m[2] - middle.position_m[2]);
  x = (x_m - middle.position_m[0] - offset_m_[0]) / scale;
  y = (y_m - middle.position_m[1] - offset_m_[1]) / scale;
}

void MouseMapping::pointer(double x, double y, bool turning) noexcept {
  const double cursor[2] = {finite_or_zero(x), finite_or_zero(y)};
  const DeskPose middle = workspace_.centre();
  const double scale = view_.metres_per_half_height(pose_.position_m[2] - middle.position_m[2]);
  double at[2];  // the cursor's point of the workspace, on its ray at the handle's depth
  for (int i = 0; i < 2; ++i) at[i] = middle.position_m[i] + cursor[i] * scale;
  if (turning) {
    if (have_last_ && turning_) {
      pose_.wrist_rad[0] += (cursor[0] - last_[0]) * kRadPerHalfHeight;
      pose_.wrist_rad[1] += (cursor[1] - last_[1]) * kRadPerHalfHeight;
    }
  } else if (turning_) {
    for (int i = 0; i < 2; ++i) offset_m_[i] = pose_.position_m[i] - at[i];  // carry on from where it stayed
  } else {
    for (int i = 0; i < 2; ++i) pose_.position_m[i] = at[i] + offset_m_[i];
  }
  pose_ = workspace_.clamp(pose_);
  last_[0] = cursor[0];
  last_[1] = cursor[1];
  have_last_ = true;
  turning_ = turning;
}

void MouseMapping::scroll(double notches) noexcept {
  along(pose_, direction_, finite_or_zero(notches) * kDepthPerNotch_m);
  pose_ = workspace_.clamp(pose_);  // so scrolling past the end builds up no dead zone
}

KeyboardMapping::KeyboardMapping(const DeskWorkspace& workspace) : workspace_(workspace), pose_(workspace.centre()) {}

void KeyboardMapping::press(DeskKey key, bool fine) noexcept {
  const double scale = fine ? kFine : 1.0;
  const double m = kStep_m * scale, rad = kStep_rad * scale;
  double* p = pose_.position_m;
  double* w = pose_.wrist_rad;
  switch (key) {
    case DeskKey::kLeft:
      p[0] -= m;
      break;
    case DeskKey::kRight:
      p[0] += m;
      break;
    case DeskKey::kDown:
      p[1] -= m;
      break;
    case DeskKey::kUp:
      p[1] += m;
      break;
    case DeskKey::kOut:
      along(pose_, direction_, -m);
      break;
    case DeskKey::kIn:
      along(pose_, direction_, m);
      break;
    case DeskKey::kSwingLeft:
      w[0] -= rad;
      break;
    case DeskKey::kSwingRight:
      w[0] += rad;
      break;
    case DeskKey::kTiltToward:
      w[1] -= rad;
      break;
    case DeskKey::kTiltAway:
      w[1] += rad;
      break;
  }
  pose_ = workspace_.clamp(pose_);
}

void stick_past_dead_zone(double& x, double& y, double dead_zone) noexcept {
  x = std::clamp(finite_or_zero(x), -1.0, 1.0);
  y = std::clamp(finite_or_zero(y), -1.0, 1.0);
  const double r = std::hypot(x, y);
  if (r <= dead_zone) {
    x = y = 0.0;
    return;
  }
  const double scale = std::min((r - dead_zone) / (1.0 - dead_zone), 1.0) / r;
  x *= scale;
  y *= scale;
}

double trigger_past_dead_zone(double axis, double dead_zone) noexcept {
  const double pulled = 0.5 * (std::clamp(finite_or_zero(axis), -1.0, 1.0) + 1.0);  // 0 released, 1 pulled
  return pulled <= dead_zone ? 0.0 : (pulled - dead_zone) / (1.0 - dead_zone);
}

GamepadMapping::GamepadMapping(const DeskWorkspace& workspace, bool plunger_on_left_trigger)
    : workspace_(workspace), pose_(workspace.centre()), plunger_on_left_trigger_(plunger_on_left_trigger) {}

void GamepadMapping::update(const GamepadState& s, double dt_s) noexcept {
  const double dt = std::clamp(finite_or_zero(dt_s), 0.0, kMaxStep_s);
  double lx = s.axes[GamepadState::kLeftX], ly = s.axes[GamepadState::kLeftY];
  double rx = s.axes[GamepadState::kRightX], ry = s.axes[GamepadState::kRightY];
  stick_past_dead_zone(lx, ly, kStickDeadZone);
  stick_past_dead_zone(rx, ry, kStickDeadZone);
  const double in = trigger_past_dead_zone(s.axes[GamepadState::kRightTrigger], kTriggerDeadZone);
  const double depth = plunger_on_left_trigger_
                           ? (s.buttons[GamepadState::kLeftBumper] ? -in : in)
                           : in - trigger_past_dead_zone(s.axes[GamepadState::kLeftTrigger], kTriggerDeadZone);
  const double move = kSpeed_m_per_s * dt, turn = kTurnRate_rad_per_s * dt;
  pose_.position_m[0] += move * lx;
  pose_.position_m[1] -= move * ly;  // the stick's y points down
  along(pose_, direction_, move * depth);
  pose_.wrist_rad[0] += turn * rx;
  pose_.wrist_rad[1] -= turn * ry;
  pose_ = workspace_.clamp(pose_);

  const bool held = s.buttons[kResetFault] != 0;
  if (held && !reset_held_) reset_pressed_ = true;
  reset_held_ = held;
}

void PlungerMapping::held(bool down, double dt_s) noexcept {
  const double dt = std::clamp(finite_or_zero(dt_s), 0.0, GamepadMapping::kMaxStep_s);
  force_N_ = down ? std::min(kHeldForce_N, force_N_ + kHeldForce_N * dt / kRise_s) : 0.0;
}

void PlungerMapping::trigger(double axis) noexcept {
  force_N_ = kHeldForce_N * trigger_past_dead_zone(axis, GamepadMapping::kTriggerDeadZone);
}

bool GamepadMapping::take_fault_reset() noexcept {
  const bool pressed = reset_pressed_;
  reset_pressed_ = false;
  return pressed;
}

}  // namespace needle::haptics
