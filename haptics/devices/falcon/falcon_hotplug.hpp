// Hot-plug notices for Novint Falcons (USB 0403:cb48) through libusb's hotplug callbacks, on
// a thread of its own. The app polls arrivals()/departures() from its UI thread: after a
// departure the loop's safety monitor has already latched "device disconnected"; after an
// arrival the app reopens the device (close(), open()) and resets the fault.
#pragma once

#include <atomic>
#include <cstdint>
#include <string>
#include <thread>

struct libusb_context;

namespace needle::haptics::falcon {

class FalconHotplug {
 public:
  // Starts watching; supported() is false (with reason()) when this libusb or platform has
  // no hotplug support, in which case `needle-sim devices` rescans instead.
  FalconHotplug();
  ~FalconHotplug();
  FalconHotplug(const FalconHotplug&) = delete;
  FalconHotplug& operator=(const FalconHotplug&) = delete;

  bool supported() const noexcept { return supported_; }
  const std::string& reason() const noexcept { return reason_; }
  // Counts since construction; Falcons already plugged in count as arrivals.
  uint64_t arrivals() const noexcept { return counts_.arrivals.load(); }
  uint64_t departures() const noexcept { return counts_.departures.load(); }

  // Written by libusb's callback (its user data).
  struct Counts {
    std::atomic<uint64_t> arrivals{0};
    std::atomic<uint64_t> departures{0};
  };

 private:
  libusb_context* context_ = nullptr;
  int handle_ = 0;
  bool supported_ = false;
  std::string reason_;
  Counts counts_;
  std::atomic<bool> stop_{false};
  std::thread thread_;
};

}  // namespace needle::haptics::falcon
