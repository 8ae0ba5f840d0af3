// The `mouse` device for trainees without a haptic device: the handle follows the window's
// cursor in x and y and the scroll wheel (or keys) in depth. It has no actuators, so the
// forces are shown on screen instead of felt (the command is discarded).
#pragma once

#include "haptics/devices/haptic_device.hpp"
#include "haptics/sync/seqlock.hpp"

namespace needle::haptics {

struct MouseMapping {
  double workspace_min_m[3] = {-0.1, -0.1, 0.0};
  double workspace_max_m[3] = {0.1, 0.1, 0.2};
  double depth_per_step_m = 0.002;  // one scroll notch or key press
};

class MouseDevice : public HapticDevice {
 public:
  explicit MouseDevice(const MouseMapping& mapping = {});

  // The app's event thread (one writer): cursor in normalised window coordinates, x right
  // and y up in [-1, 1] (clamped), depth steps accumulated. Lock-free.
  void set_pointer(double x_norm, double y_norm) noexcept;
  void add_depth_steps(double steps) noexcept;
  void set_buttons(uint32_t buttons) noexcept;

  void open() override {}
  void close() noexcept override {}
  void home() override {}
  const DeviceCapabilities& capabilities() const noexcept override { return caps_; }
  void read(DeviceReading& out) noexcept override;
  void write(const DeviceCommand&) noexcept override {}

 private:
  struct Input {
    double x_norm = 0.0;
    double y_norm = 0.0;
    double depth_steps = 0.0;
    uint32_t buttons = 0;
  };

  MouseMapping mapping_;
  DeviceCapabilities caps_;
  Input writer_copy_;  // writer thread only
  SeqLock<Input> input_;
  uint64_t sequence_ = 0;
};

}  // namespace needle::haptics
