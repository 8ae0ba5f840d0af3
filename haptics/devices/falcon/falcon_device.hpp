// The Novint Falcon through libusb, written in this project (no libftdi, no libnifalcon).
// The Falcon is an FTDI FT232 USB-serial bridge in front of a microcontroller that runs
// firmware loaded at every power-up; Novint's firmware file (novint.bin) may not be
// redistributed, so the user supplies it (--firmware FILE). Sequence and timings follow
// libnifalcon's FalconCommLibUSB and FalconFirmware (documented in docs/DEVICES.md).
//
// In the loop, read() and write() never block: one bulk IN and one bulk OUT transfer stay
// allocated and are polled with a zero timeout.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "haptics/devices/falcon/falcon_kinematics.hpp"
#include "haptics/devices/falcon/falcon_protocol.hpp"
#include "haptics/devices/haptic_device.hpp"

struct libusb_context;
struct libusb_device_handle;
struct libusb_transfer;

namespace needle::haptics::falcon {

struct FalconOptions {
  int index = 0;              // which Falcon when several are plugged in
  std::string firmware_path;  // empty: the firmware must already be running
  int firmware_retries = 5;
  double max_torque_nm = 3.0;  // per motor; 30000 counts, inside the int16 command range
  double homing_timeout_s = 30.0;
  Geometry geometry;
  Drive drive;
};

struct UsbPresence {
  int count = 0;      // Falcons on the bus
  std::string error;  // why the bus could not be scanned, empty when it could
};

// Scans the USB bus for 0403:cb48 (no device is opened).
UsbPresence find_falcons();

class FalconDevice : public HapticDevice {
 public:
  explicit FalconDevice(FalconOptions options);
  ~FalconDevice() override;

  void open() override;
  void close() noexcept override;
  void home() override;
  const DeviceCapabilities& capabilities() const noexcept override { return caps_; }
  void read(DeviceReading& out) noexcept override;
  void write(const DeviceCommand& command) noexcept override;

 private:
  void control(uint8_t request, uint16_t value, uint16_t index, const char* what);
  void send_blocking(const uint8_t* bytes, int count, const char* what);
  // Reads until `count` payload bytes (FTDI status stripped) arrived or timeout_ms passed.
  std::size_t receive_blocking(uint8_t* payload, std::size_t count, int timeout_ms);
  void set_baud(double baud, const char* what);
  bool enter_firmware_mode();
  bool upload_firmware(const std::vector<uint8_t>& image);
  void enter_normal_mode();
  void start_streaming();
  void poll_events() noexcept;
  static void transfer_done(libusb_transfer* transfer);

  FalconOptions options_;
  DeviceCapabilities caps_;
  libusb_context* context_ = nullptr;
  libusb_device_handle* handle_ = nullptr;
  libusb_transfer* in_ = nullptr;
  libusb_transfer* out_ = nullptr;
  uint8_t in_buffer_[64] = {};
  uint8_t out_buffer_[kFrameSize] = {};
  bool in_flight_ = false;
  bool out_flight_ = false;
  bool disconnected_ = false;
  FrameAssembler assembler_;
  DeviceStatus status_;
  MotorCommand command_;
  uint64_t sequence_ = 0;
  Vec3 position_ = {0.0, 0.0, 0.11};
  Vec3 hip_{};
};

}  // namespace needle::haptics::falcon
