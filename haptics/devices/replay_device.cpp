#include "haptics/devices/replay_device.hpp"

namespace needle::haptics {

ReplayDevice::ReplayDevice(std::string path) : path_(std::move(path)) { caps_.name = "replay:" + path_; }

void ReplayDevice::open() {
  RecordingReader reader(path_);
  header_ = reader.header();
  readings_.clear();
  next_ = 0;
  std::vector<TickSample> block;
  while (reader.next(block)) {
    // Commands are discarded, but the loop builds them in the recorded space so the safety
    // monitor and the step see the session as it was.
    if (readings_.empty()) {
      caps_.command_space = block.front().command.space;
      caps_.joint_count = block.front().command.joint_count;
    }
    for (const TickSample& s : block) readings_.push_back(s.reading);
  }
  end_ = reader.end();
}

void ReplayDevice::read(DeviceReading& out) noexcept {
  if (finished()) {
    out.connected = 0;
    return;
  }
  out = readings_[next_++];
}

}  // namespace needle::haptics
