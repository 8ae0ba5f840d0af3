#include "haptics/devices/replay_device.hpp"

namespace needle::haptics {

ReplayDevice::ReplayDevice(std::string path) : path_(std::move(path)) { caps_.name = "replay:" + path_; }

void ReplayDevice::open() {
  RecordingReader reader(path_);
  header_ = reader.header();
  readings_.clear();
  held_back_.clear();
  next_ = 0;
  std::vector<TickSample> block;
  while (reader.next(block)) {
    // The loop builds its commands in the recorded space so the safety monitor and the step see
    // the session as it was.
    if (readings_.empty()) {
      caps_.command_space = block.front().command.space;
      caps_.joint_count = block.front().command.joint_count;
    }
    for (const TickSample& s : block) {
      readings_.push_back(s.reading);
      held_back_.push_back((s.state.limits & kLimitForce) != 0);
    }
  }
  end_ = reader.end();
}

bool ReplayDevice::held_back() const noexcept {
  return next_ > 0 && next_ <= held_back_.size() && held_back_[next_ - 1];
}

void ReplayDevice::read(DeviceReading& out) noexcept {
  if (finished()) {
    out.connected = 0;
    return;
  }
  out = readings_[next_++];
}

}  // namespace needle::haptics
