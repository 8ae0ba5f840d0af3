// `replay:FILE`: plays a recorded session's device stream back tick by tick. Fed to the
// same step on the same build, it reproduces the recorded simulation state bit for bit.
// After the last record the device reads as disconnected, so the safety monitor ramps any
// force to zero. open() reads the recording through its checks, a block at a time, and keeps
// the readings and whether the device held each tick's force back, so a damaged recording is refused
// before the first tick.
#pragma once

#include <string>
#include <vector>

#include "haptics/devices/haptic_device.hpp"
#include "haptics/recording/session_format.hpp"

namespace needle::haptics {

class ReplayDevice : public HapticDevice {
 public:
  explicit ReplayDevice(std::string path);

  // Reads the recording's readings (throws RecordingError naming the file and the element).
  void open() override;
  void close() noexcept override {}
  void home() override {}
  const DeviceCapabilities& capabilities() const noexcept override { return caps_; }
  void read(DeviceReading& out) noexcept override;
  void write(const DeviceCommand&) noexcept override {}
  // Whether the recorded device held the tick last read back (its kLimitForce mark).
  bool held_back() const noexcept override;

  const SessionHeader& header() const noexcept { return header_; }
  // Whether the file was closed, cut short or has no checksums (valid after open()).
  const RecordingEnd& end() const noexcept { return end_; }
  std::size_t length() const noexcept { return readings_.size(); }
  bool finished() const noexcept { return next_ >= readings_.size(); }

 private:
  std::string path_;
  DeviceCapabilities caps_;
  SessionHeader header_;
  RecordingEnd end_;
  std::vector<DeviceReading> readings_;
  std::vector<uint8_t> held_back_;
  std::size_t next_ = 0;
};

}  // namespace needle::haptics
