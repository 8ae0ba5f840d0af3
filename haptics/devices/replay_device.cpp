#include "haptics/devices/replay_device.hpp"

namespace needle::haptics {

ReplayDevice::ReplayDevice(std::string path) : path_(std::move(path)) { caps_.name = "replay:" + path_; }

void ReplayDevice::open() {
  session_ = read_session(path_);
  next_ = 0;
  // Commands are discarded, but the loop builds them in the recorded space so the safety
  // monitor and the step see the session as it was.
  if (!session_.records.empty()) {
    caps_.command_space = session_.records.front().command.space;
    caps_.joint_count = session_.records.front().command.joint_count;
  }
}

void ReplayDevice::read(DeviceReading& out) noexcept {
  if (finished()) {
    out.connected = 0;
    return;
  }
  out = session_.records[next_++].reading;
}

}  // namespace needle::haptics
