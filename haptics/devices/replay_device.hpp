// `replay:FILE`: plays a recorded session's device stream back tick by tick. Fed to the
// same step on the same build, it reproduces the recorded simulation state bit for bit.
// After the last record the device reads as disconnected, so the safety monitor ramps any
// force to zero.
#pragma once

#include <string>
#include <vector>

#include "haptics/devices/haptic_device.hpp"
#include "haptics/recording/session_format.hpp"

namespace needle::haptics {

class ReplayDevice : public HapticDevice {
 public:
  explicit ReplayDevice(std::string path);

  // Loads the whole recording (throws RecordingError naming the file and element).
  void open() override;
  void close() noexcept override {}
  void home() override {}
  const DeviceCapabilities& capabilities() const noexcept override { return caps_; }
  void read(DeviceReading& out) noexcept override;
  void write(const DeviceCommand&) noexcept override {}

  const SessionHeader& header() const noexcept { return session_.header; }
  std::size_t length() const noexcept { return session_.records.size(); }
  bool finished() const noexcept { return next_ >= session_.records.size(); }

 private:
  std::string path_;
  DeviceCapabilities caps_;
  Session session_;
  std::size_t next_ = 0;
};

}  // namespace needle::haptics
