#include "haptics/devices/syringe_hand.hpp"

#include <algorithm>
#include <cmath>

namespace needle::haptics {

SyringeHandDevice::SyringeHandDevice(std::unique_ptr<HapticDevice> needle, std::unique_ptr<HapticDevice> second)
    : needle_(std::move(needle)), second_(std::move(second)) {
  if (!needle_) throw DeviceError("syringe hand: no device for the needle");
}

void SyringeHandDevice::open() {
  needle_->open();
  if (second_) second_->open();
}

void SyringeHandDevice::close() noexcept {
  if (second_) second_->close();
  needle_->close();
}

void SyringeHandDevice::home() {
  needle_->home();
  if (second_) second_->home();
  second_started_ = false;
}

void SyringeHandDevice::read(DeviceReading& out) noexcept {
  needle_->read(out);
  if (!second_) {
    const double force = thumb_.load();
    out.plunger_input = uint32_t(PlungerInput::kThumbForce);
    out.plunger_force_n = std::isfinite(force) && force > 0.0 ? force : 0.0;
    return;
  }
  second_->read(second_reading_);
  if (!second_started_ && second_reading_.connected) {  // the plunger starts where the handle is
    second_start_z_ = second_reading_.position_m[2];
    second_started_ = true;
  }
  out.connected = out.connected && second_reading_.connected;
  out.plunger_input = uint32_t(PlungerInput::kHandlePosition);
  out.plunger_position_m = second_started_ ? second_start_z_ - second_reading_.position_m[2] : 0.0;
}

void SyringeHandDevice::write(const DeviceCommand& command) noexcept {
  needle_->write(command);
  if (!second_) return;
  DeviceCommand back;
  back.space = CommandSpace::kTaskForce;
  const double most = second_->capabilities().max_force_n;
  back.force_n[2] = most > 0.0 ? std::min(command.plunger_force_n, most) : command.plunger_force_n;
  second_->write(back);
}

}  // namespace needle::haptics
