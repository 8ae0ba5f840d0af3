// What the desk devices' input does to their pose (haptics/devices/desk_device.hpp), below any
// window system: the app reads the mouse, the keys and the gamepad (app/desk_input.cpp) and hands
// them here as plain values, so every mapping is tested without a display. The limits and the
// reasons for them are in docs/DEVICES.md, "Desk devices". All of this runs on the app's input
// thread, never in the haptic tick.
#pragma once

#include <cstdint>

#include "haptics/devices/desk_device.hpp"

namespace needle::haptics {

// How the 3D view shows the handle (a pinhole camera, the vertical field of view across the
// window's height): the mouse puts the handle where the cursor's ray meets the plane square to the
// view at the handle's depth, so the tip comes to rest under the cursor (docs/DEVICES.md).
struct MouseView {
  double tan_half_fov = 0.5;      // tan of half the vertical field of view
  double start_distance_m = 0.2;  // from the camera to the tool's start, along the view
  // Metres in that plane for half the window's height, the handle `depth_m` deeper than its start:
  // (start_distance + depth) tan(fov/2). The defaults give a tenth of a metre at the start.
  double metres_per_half_height(double depth_m) const noexcept { return (start_distance_m + depth_m) * tan_half_fov; }
};

// The direction the needle points in device axes (unit): where the wheel, W and S and the triggers
// push the handle, along the needle rather than into the screen. The app sets it each frame from the
// wrist (haptics::wrist_direction); the default is into the view.
struct NeedleDirection {
  double device[3] = {0.0, 0.0, 1.0};
};

// The mouse: the cursor moves the handle in the view's plane, under the cursor (MouseView); the
// wheel pushes it along the needle (NeedleDirection), after which the app puts the cursor on the
// handle again (cursor_at_handle), so cursor and tip stay together. With the turning button held
// (the right one), cursor motion turns the wrist instead, as if the mouse held the needle's hub:
// right swings it clockwise as seen, up (forward on the desk) tilts the hub away; the handle stays
// where it is and, once the button is released, moves on from there (the app puts the cursor back
// where the turn began).
class MouseMapping {
 public:
  // 90° for half the window's height: design value, the largest turn a shipped task asks (the
  // penetrable sphere's 45° pivot) is a quarter of the window's height, a comfortable sweep, and a
  // pixel of a 720-pixel window is 0.25°, a twentieth of the tightest tolerance (5°).
  static constexpr double kRadPerHalfHeight = 1.5707963267948966;
  static constexpr double kDepthPerNotch_m = 0.002;  // 2 mm a notch: a 3 cm insertion is 15 notches

  explicit MouseMapping(const DeskWorkspace& workspace = {}, const MouseView& view = {});

  // The cursor from the window's centre in half window heights: x to the right (± the aspect
  // ratio at the edges), y up (±1 at the edges).
  void pointer(double x, double y, bool turning) noexcept;
  // Wheel notches, forward (in along the needle) positive.
  void scroll(double notches) noexcept;
  void set_needle_direction(const NeedleDirection& direction) noexcept { direction_ = direction; }
  const DeskPose& pose() const noexcept { return pose_; }
  // Where the cursor puts the handle at (x, y) in the view's plane (device metres), at its depth
  // now, in pointer()'s terms: after the wheel, the cursor goes here.
  void cursor_for(double x_m, double y_m, double& x, double& y) const noexcept;
  void cursor_at_handle(double& x, double& y) const noexcept {
    cursor_for(pose_.position_m[0], pose_.position_m[1], x, y);
  }

 private:
  DeskWorkspace workspace_;
  MouseView view_;
  NeedleDirection direction_;
  DeskPose pose_;
  double offset_m_[2] = {0.0, 0.0};  // handle minus the cursor's point, changed only by a turn
  double last_[2] = {0.0, 0.0};
  bool have_last_ = false;
  bool turning_ = false;
};

// The keyboard, one step a press (the system's key repeat gives steps while a key is held).
enum class DeskKey {
  kLeft,
  kRight,
  kDown,
  kUp,  // the handle in the view's plane (arrow keys)
  kOut,
  kIn,  // depth: out of the view, into it (S, W)
  kSwingLeft,
  kSwingRight,  // the hub left or right about the tip (A, D)
  kTiltToward,
  kTiltAway,  // the hub towards the viewer or away (Q, E)
};

class KeyboardMapping {
 public:
  static constexpr double kStep_m = 0.001;
  static constexpr double kStep_rad = 0.017453292519943295;  // 1°
  static constexpr double kFine = 0.2;                       // with Shift: a fifth of a step

  explicit KeyboardMapping(const DeskWorkspace& workspace = {});
  // In and out (W, S) go along the needle.
  void press(DeskKey key, bool fine) noexcept;
  void set_needle_direction(const NeedleDirection& direction) noexcept { direction_ = direction; }
  const DeskPose& pose() const noexcept { return pose_; }

 private:
  DeskWorkspace workspace_;
  NeedleDirection direction_;
  DeskPose pose_;
};

// A gamepad in GLFW's standard layout (GLFWgamepadstate) as plain values.
struct GamepadState {
  enum Axis { kLeftX, kLeftY, kRightX, kRightY, kLeftTrigger, kRightTrigger, kAxes };
  enum Button {
    kA,
    kB,
    kX,
    kY,
    kLeftBumper,
    kRightBumper,
    kBack,
    kStart,
    kGuide,
    kLeftThumb,
    kRightThumb,
    kDpadUp,
    kDpadRight,
    kDpadDown,
    kDpadLeft,
    kButtons
  };
  // Sticks in [-1, 1] with y down; triggers from -1 (released) to 1 (pulled).
  float axes[kAxes] = {0.0f, 0.0f, 0.0f, 0.0f, -1.0f, -1.0f};
  uint8_t buttons[kButtons] = {};
};

// Rate control: the left stick moves the handle in the view's plane, the right trigger pushes it
// in along the needle and the left one draws it back, the right stick turns the wrist (right swings the
// hub clockwise, up tilts it away), each at a speed proportional to the deflection past a dead
// zone. Start resets a latched fault. In a task with a syringe the left trigger is the thumb on the
// plunger (PlungerMapping) and the right trigger draws the needle back while the left bumper is held.
class GamepadMapping {
 public:
  static constexpr double kSpeed_m_per_s = 0.02;                     // stick or trigger fully deflected
  static constexpr double kTurnRate_rad_per_s = 0.5235987755982988;  // 30°/s
  static constexpr double kStickDeadZone = 0.15;                     // of the stick's radius
  static constexpr double kTriggerDeadZone = 0.05;                   // of the trigger's travel
  static constexpr double kMaxStep_s = 0.1;                          // a longer frame moves as much as this one
  static constexpr GamepadState::Button kResetFault = GamepadState::kStart;

  explicit GamepadMapping(const DeskWorkspace& workspace = {}, bool plunger_on_left_trigger = false);

  // One frame of `dt_s` seconds with the state read at its start.
  void update(const GamepadState& state, double dt_s) noexcept;
  void set_needle_direction(const NeedleDirection& direction) noexcept { direction_ = direction; }
  const DeskPose& pose() const noexcept { return pose_; }
  // True once for each press of the reset button.
  bool take_fault_reset() noexcept;

 private:
  DeskWorkspace workspace_;
  NeedleDirection direction_;
  DeskPose pose_;
  bool plunger_on_left_trigger_ = false;
  bool reset_held_ = false;
  bool reset_pressed_ = false;
};

// The thumb on the loss-of-resistance syringe's plunger from a desk (docs/DEVICES.md, "The syringe
// hand"): a key or a button held presses with a force rising linearly to kHeldForce_N over kRise_s
// and staying there, released lets go at once; a gamepad's trigger presses in proportion to its
// pull past the dead zone, kHeldForce_N fully pulled. Design values: 12 N is a little above the
// 11.1 to 11.8 N Vaughan et al. (2012) measured on the plunger in ligament, so that a trainee can
// press as a clinician does; one second of rise lets a press be eased on, as a thumb does.
class PlungerMapping {
 public:
  static constexpr double kHeldForce_N = 12.0;
  static constexpr double kRise_s = 1.0;

  // One frame of `dt_s` seconds with the key or button held (`down`) or not.
  void held(bool down, double dt_s) noexcept;
  // The trigger's axis, -1 released to 1 pulled.
  void trigger(double axis) noexcept;
  double force_N() const noexcept { return force_N_; }

 private:
  double force_N_ = 0.0;
};

// The deflection past a dead zone, rescaled so that the dead zone's edge is 0 and full deflection
// is 1: for a stick the radial deflection (x, y) in place, for a trigger from -1 (released).
void stick_past_dead_zone(double& x, double& y, double dead_zone) noexcept;
double trigger_past_dead_zone(double axis, double dead_zone) noexcept;

}  // namespace needle::haptics
