// The syringe hand of a live session (docs/DEVICES.md, "The syringe hand"): a HapticDevice around
// the device that holds the needle, adding to each of its readings what presses the
// loss-of-resistance syringe's plunger. Either a thumb force the app sets from its own thread,
// lock-free (a key held, a mouse button, a gamepad's trigger), or a second position device (a
// second Falcon), whose handle pushed along -z (away from the trainee) is the plunger's push and
// which is sent the plunger's push back along +z. Its capabilities are the needle's device's; a
// second device that is gone reads as the needle's device gone (the loop latches the fault).
#pragma once

#include <memory>

#include "haptics/devices/haptic_device.hpp"
#include "haptics/sync/seqlock.hpp"

namespace needle::haptics {

class SyringeHandDevice : public HapticDevice {
 public:
  // `second`: the syringe hand's own device (nullptr: the app's thumb force). Both opened, homed
  // and closed with this one.
  explicit SyringeHandDevice(std::unique_ptr<HapticDevice> needle, std::unique_ptr<HapticDevice> second = nullptr);

  // The app's thread (one writer): the thumb's force on the plunger, N (without a second device).
  void set_thumb_force(double force_n) noexcept { thumb_.store(force_n); }
  bool has_second() const noexcept { return second_ != nullptr; }
  HapticDevice& needle() noexcept { return *needle_; }

  void open() override;
  void close() noexcept override;
  void home() override;
  const DeviceCapabilities& capabilities() const noexcept override { return needle_->capabilities(); }
  void read(DeviceReading& out) noexcept override;
  void write(const DeviceCommand& command) noexcept override;
  bool held_back() const noexcept override { return needle_->held_back(); }

 private:
  std::unique_ptr<HapticDevice> needle_, second_;
  SeqLock<double> thumb_;
  DeviceReading second_reading_;
  bool second_started_ = false;
  double second_start_z_ = 0.0;
};

}  // namespace needle::haptics
