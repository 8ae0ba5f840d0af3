// The desk devices, for trainees without a haptic device: the mouse, the keyboard and a gamepad
// (docs/DEVICES.md, "Desk devices"). None senses or exerts force: the forces are shown on
// screen instead of felt (the command is discarded). The app turns the device's input into a
// pose (haptics/devices/desk_mapping.hpp) and sets it here from its own thread, lock-free; every
// tick reads the newest. A pose is a handle position and the two angles of a virtual wrist,
// reported as the reading's two joints, which the task-space coupling turns into the needle's
// target direction about its tip (TaskCoupling::wrist).
#pragma once

#include "haptics/devices/device_spec.hpp"
#include "haptics/devices/haptic_device.hpp"
#include "haptics/sync/seqlock.hpp"

namespace needle::haptics {

// Where a desk device's handle is, device frame: x to the view's right, y to its up, z into the
// view; and its wrist (haptics::wrist_direction): swing, clockwise as seen, and tilt, the
// needle's hub away from the viewer.
struct DeskPose {
  double position_m[3] = {0.0, 0.0, 0.1};
  double wrist_rad[2] = {0.0, 0.0};  // swing, tilt
};

// The reach of a desk device: a box for the handle and limits for the wrist. The handle starts at
// the box's centre and its first reading lands on the tool's start, so the box is the reach around
// it: 20 cm each way in the view's plane (a task's needle travels up to about 11 cm), 10 cm in
// depth.
struct DeskWorkspace {
  double min_m[3] = {-0.2, -0.2, 0.0};
  double max_m[3] = {0.2, 0.2, 0.2};
  double swing_limit_rad = 3.141592653589793;  // ±180°
  double tilt_limit_rad = 1.3962634015954636;  // ±80°: the needle never points along the view

  DeskPose centre() const noexcept;
  // The pose brought inside the reach; a non-finite value goes to the centre's.
  DeskPose clamp(const DeskPose& pose) const noexcept;
};

class DeskDevice : public HapticDevice {
 public:
  // The desk device `spec` names (mouse, keyboard, gamepad[:N]), its capabilities' name the
  // spec's text. Throws DeviceError for a spec of another kind.
  explicit DeskDevice(const DeviceSpec& spec, const DeskWorkspace& workspace = {});

  // The app's input thread (one writer), lock-free. The pose is clamped to the workspace.
  void set_pose(const DeskPose& pose) noexcept;
  void set_buttons(uint32_t buttons) noexcept;
  // False while the input is gone (a gamepad unplugged): the loop latches a disconnection fault.
  void set_connected(bool connected) noexcept;
  const DeskWorkspace& workspace() const noexcept { return workspace_; }
  const DeviceSpec& spec() const noexcept { return spec_; }

  void open() override {}
  void close() noexcept override {}
  void home() override {}
  const DeviceCapabilities& capabilities() const noexcept override { return caps_; }
  // Position, the wrist as joints 0 (swing) and 1 (tilt), the buttons; always fresh.
  void read(DeviceReading& out) noexcept override;
  void write(const DeviceCommand&) noexcept override {}

 private:
  struct Input {
    DeskPose pose;
    uint32_t buttons = 0;
    uint32_t connected = 1;
  };

  DeviceSpec spec_;
  DeskWorkspace workspace_;
  DeviceCapabilities caps_;
  Input writer_copy_;  // writer thread only
  SeqLock<Input> input_;
  uint64_t sequence_ = 0;
};

}  // namespace needle::haptics
