#include "haptics/devices/falcon/falcon_device.hpp"

#include <libusb.h>

#include <chrono>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <thread>

#include "haptics/devices/falcon/ftdi_requests.hpp"

namespace needle::haptics::falcon {
namespace {

constexpr int kControlTimeoutMs = 1000;
constexpr std::size_t kUsbPacket = 64;
// Firmware goes out in chunks the FTDI echoes back: 62 bytes fill one 64-byte USB packet
// with its two status bytes (libnifalcon FalconFirmware::loadFirmware).
constexpr std::size_t kFirmwareChunk = 62;
constexpr double kNormalBaud = 1456312.0;
constexpr double kFirmwareCheckBaud = 9600.0;
constexpr double kFirmwareLoadBaud = 140000.0;

std::string usb_error(int code) { return std::string(libusb_error_name(code)); }

// The largest firmware image read: 1 MiB. Design value: a USB controller's firmware is kilobytes;
// the bound turns a wrong file (a disk image, /dev/zero) into an error before it is read.
constexpr std::uintmax_t kMaxFirmwareBytes = 1u << 20;

std::vector<uint8_t> read_firmware(const std::string& path) {
  std::error_code ec;
  const auto status = std::filesystem::status(path, ec);
  // Checked before it is opened: a FIFO would block the open, a device never end.
  if (std::filesystem::exists(status) && !std::filesystem::is_regular_file(status))
    throw DeviceError("falcon: firmware file " + path + ": not a regular file (a device, a pipe or a folder)");
  if (std::filesystem::exists(status) && std::filesystem::file_size(path, ec) > kMaxFirmwareBytes)
    throw DeviceError("falcon: firmware file " + path + ": larger than 1 MiB, expected Novint's firmware image");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw DeviceError("falcon: firmware file " + path + ": cannot be opened");
  std::vector<uint8_t> image((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (image.empty()) throw DeviceError("falcon: firmware file " + path + ": empty, expected Novint's firmware image");
  return image;
}

bool is_falcon(libusb_device* device) {
  libusb_device_descriptor d{};
  return libusb_get_device_descriptor(device, &d) == 0 && d.idVendor == kVendorId && d.idProduct == kProductId;
}

}  // namespace

UsbPresence find_falcons() {
  UsbPresence presence;
  libusb_context* context = nullptr;
  if (const int rc = libusb_init(&context); rc != 0) {
    presence.error = "libusb_init failed: " + usb_error(rc);
    return presence;
  }
  libusb_device** list = nullptr;
  const ssize_t n = libusb_get_device_list(context, &list);
  if (n < 0) presence.error = "cannot list USB devices: " + usb_error(static_cast<int>(n));
  for (ssize_t i = 0; i < n; ++i) presence.count += is_falcon(list[i]) ? 1 : 0;
  if (list != nullptr) libusb_free_device_list(list, 1);
  libusb_exit(context);
  return presence;
}

FalconDevice::FalconDevice(FalconOptions options) : options_(std::move(options)) {
  caps_.name = "falcon";
  caps_.command_space = CommandSpace::kTaskForce;
  caps_.actuated_axes = 3;
  caps_.joint_count = 3;
  // The box the kinematic model reaches everywhere (tests/haptics/test_falcon_kinematics.cpp
  // walks it); the real handle stops a little inside.
  caps_.workspace_min_m[0] = caps_.workspace_min_m[1] = -0.04;
  caps_.workspace_max_m[0] = caps_.workspace_max_m[1] = 0.04;
  caps_.workspace_min_m[2] = 0.09;
  caps_.workspace_max_m[2] = 0.15;
  caps_.max_force_n = 9.0;  // Novint's specification: "over 2 lbs" (about 9 N)
  for (int i = 0; i < 3; ++i) caps_.max_torque_nm[i] = options_.max_torque_nm;
  caps_.max_stiffness_n_per_m = 2000.0;  // typical stable wall on a Falcon at 1 kHz (docs/DEVICES.md)
}

FalconDevice::~FalconDevice() { close(); }

void FalconDevice::control(uint8_t request, uint16_t value, uint16_t index, const char* what) {
  const int rc =
      libusb_control_transfer(handle_, ftdi::kRequestTypeOut, request, value, index, nullptr, 0, kControlTimeoutMs);
  if (rc < 0) throw DeviceError(std::string("falcon: FTDI request failed (") + what + "): " + usb_error(rc));
}

void FalconDevice::set_baud(double baud, const char* what) {
  const ftdi::BaudSetting b = ftdi::baud_setting(baud);
  control(ftdi::kSetBaudRate, b.value, b.index, what);
}

void FalconDevice::send_blocking(const uint8_t* bytes, int count, const char* what) {
  int sent = 0;
  const int rc =
      libusb_bulk_transfer(handle_, ftdi::kEndpointOut, const_cast<uint8_t*>(bytes), count, &sent, kControlTimeoutMs);
  if (rc != 0 || sent != count)
    throw DeviceError(std::string("falcon: USB write failed (") + what + "): " + usb_error(rc));
}

std::size_t FalconDevice::receive_blocking(uint8_t* payload, std::size_t count, int timeout_ms) {
  std::size_t got = 0;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::milliseconds(timeout_ms);
  uint8_t packet[kUsbPacket];
  while (got < count && std::chrono::steady_clock::now() < deadline) {
    int n = 0;
    const int rc = libusb_bulk_transfer(handle_, ftdi::kEndpointIn, packet, sizeof packet, &n, 100);
    if (rc != 0 && rc != LIBUSB_ERROR_TIMEOUT) throw DeviceError("falcon: USB read failed: " + usb_error(rc));
    uint8_t data[kUsbPacket];
    const std::size_t len = strip_ftdi_status(packet, static_cast<std::size_t>(n), data);
    for (std::size_t i = 0; i < len && got < count; ++i) payload[got++] = data[i];
  }
  return got;
}

// The bootloader handshake of libnifalcon's FalconCommLibUSB::setFirmwareMode: 9600 8N1,
// no flow control, RTS low, DTR pulsed; "\n C \r" must be answered "\n D , \r"; then DTR
// low, 140 kbaud, and 'A' must be echoed.
bool FalconDevice::enter_firmware_mode() {
  control(ftdi::kReset, ftdi::kPurgeRx, 0, "purge RX");
  control(ftdi::kReset, ftdi::kPurgeTx, 0, "purge TX");
  control(ftdi::kReset, ftdi::kResetSio, 0, "reset");
  control(ftdi::kSetLatencyTimer, 16, 0, "latency 16 ms");
  set_baud(kFirmwareCheckBaud, "9600 baud");
  control(ftdi::kSetData, ftdi::kLine8N1, 0, "8N1");
  control(ftdi::kSetFlowCtrl, ftdi::kNoFlowControl, 0, "no flow control");
  control(ftdi::kModemCtrl, ftdi::kRtsLow, 0, "RTS low");
  control(ftdi::kModemCtrl, ftdi::kDtrLow, 0, "DTR low");
  control(ftdi::kModemCtrl, ftdi::kDtrHigh, 0, "DTR high");
  const uint8_t hello[3] = {0x0A, 0x43, 0x0D};
  const uint8_t answer[4] = {0x0A, 0x44, 0x2C, 0x0D};
  bool answered = false;
  for (int attempt = 0; attempt < 100 && !answered; ++attempt) {
    send_blocking(hello, 3, "bootloader hello");
    uint8_t reply[4] = {};
    answered = receive_blocking(reply, 4, 100) == 4 && std::memcmp(reply, answer, 4) == 0;
  }
  if (!answered) return false;
  control(ftdi::kModemCtrl, ftdi::kDtrLow, 0, "DTR low");
  set_baud(kFirmwareLoadBaud, "140000 baud");
  const uint8_t a = 0x41;
  send_blocking(&a, 1, "bootloader 'A'");
  uint8_t echo = 0;
  return receive_blocking(&echo, 1, 1000) == 1 && echo == 0x41;
}

// Every chunk is echoed by the bootloader; the echo must match byte for byte.
bool FalconDevice::upload_firmware(const std::vector<uint8_t>& image) {
  if (!enter_firmware_mode()) return false;
  uint8_t echo[kFirmwareChunk];
  for (std::size_t at = 0; at < image.size(); at += kFirmwareChunk) {
    const std::size_t n = std::min(kFirmwareChunk, image.size() - at);
    send_blocking(&image[at], static_cast<int>(n), "firmware chunk");
    if (receive_blocking(echo, n, 1000) != n || std::memcmp(echo, &image[at], n) != 0) return false;
  }
  return true;
}

void FalconDevice::enter_normal_mode() {
  control(ftdi::kSetLatencyTimer, 1, 0, "latency 1 ms");
  set_baud(kNormalBaud, "normal-mode baud");
}

void FalconDevice::open() {
  if (handle_ != nullptr) return;
  std::vector<uint8_t> firmware;
  if (!options_.firmware_path.empty()) firmware = read_firmware(options_.firmware_path);

  if (const int rc = libusb_init(&context_); rc != 0) {
    context_ = nullptr;
    throw DeviceError("falcon: libusb_init failed: " + usb_error(rc));
  }
  libusb_device** list = nullptr;
  const ssize_t n = libusb_get_device_list(context_, &list);
  libusb_device* found = nullptr;
  for (ssize_t i = 0, seen = 0; i < n && found == nullptr; ++i)
    if (is_falcon(list[i]) && seen++ == options_.index) found = list[i];
  int rc = found == nullptr ? LIBUSB_ERROR_NO_DEVICE : libusb_open(found, &handle_);
  if (list != nullptr) libusb_free_device_list(list, 1);
  if (found == nullptr) {
    close();
    throw DeviceError("falcon: no Novint Falcon (USB 0403:cb48) number " + std::to_string(options_.index) +
                      " found; plug it in and power it (`needle-sim devices` lists what is connected)");
  }
  if (rc != 0) {
    handle_ = nullptr;
    close();
    throw DeviceError(
        "falcon: cannot open USB 0403:cb48: " + usb_error(rc) +
        (rc == LIBUSB_ERROR_ACCESS ? " (install tools/udev/99-novint-falcon.rules, see docs/DEVICES.md)" : ""));
  }
  libusb_set_auto_detach_kernel_driver(handle_, 1);  // ftdi_sio may have bound the serial port
  if ((rc = libusb_claim_interface(handle_, 0)) != 0) {
    close();
    throw DeviceError("falcon: cannot claim interface 0: " + usb_error(rc));
  }
  try {
    if (!firmware.empty()) {
      bool loaded = false;
      for (int attempt = 0; attempt < options_.firmware_retries && !loaded; ++attempt)
        loaded = upload_firmware(firmware);
      if (!loaded)
        throw DeviceError("falcon: firmware " + options_.firmware_path + " not accepted after " +
                          std::to_string(options_.firmware_retries) +
                          " attempts (echo mismatch or no bootloader answer)");
    }
    enter_normal_mode();
    start_streaming();
  } catch (...) {
    close();
    throw;
  }
}

void FalconDevice::start_streaming() {
  in_ = libusb_alloc_transfer(0);
  out_ = libusb_alloc_transfer(0);
  if (in_ == nullptr || out_ == nullptr) throw DeviceError("falcon: cannot allocate USB transfers");
  libusb_fill_bulk_transfer(in_, handle_, ftdi::kEndpointIn, in_buffer_, sizeof in_buffer_,
                            &FalconDevice::transfer_done, this, 0);
  libusb_fill_bulk_transfer(out_, handle_, ftdi::kEndpointOut, out_buffer_, sizeof out_buffer_,
                            &FalconDevice::transfer_done, this, 0);
  if (const int rc = libusb_submit_transfer(in_); rc != 0)
    throw DeviceError("falcon: cannot start reading: " + usb_error(rc));
  in_flight_ = true;
  // The firmware answers each command frame with a status frame: prime it with a zero command.
  write(DeviceCommand{});
}

void FalconDevice::transfer_done(libusb_transfer* transfer) {
  auto* self = static_cast<FalconDevice*>(transfer->user_data);
  if (transfer->status == LIBUSB_TRANSFER_NO_DEVICE) self->disconnected_ = true;
  if (transfer == self->out_) {
    self->out_flight_ = false;
    return;
  }
  self->in_flight_ = false;
  if (transfer->status == LIBUSB_TRANSFER_COMPLETED) {
    uint8_t payload[kUsbPacket];
    const std::size_t n =
        strip_ftdi_status(transfer->buffer, static_cast<std::size_t>(transfer->actual_length), payload);
    if (self->assembler_.feed(payload, n, self->status_) > 0) ++self->sequence_;
  }
}

void FalconDevice::poll_events() noexcept {
  timeval zero{0, 0};
  libusb_handle_events_timeout_completed(context_, &zero, nullptr);
  if (!in_flight_ && !disconnected_ && libusb_submit_transfer(in_) == 0) in_flight_ = true;
}

void FalconDevice::read(DeviceReading& out) noexcept {
  if (handle_ == nullptr) {
    out.connected = 0;
    return;
  }
  const uint64_t before = sequence_;
  poll_events();
  out.connected = disconnected_ ? 0 : 1;
  out.joint_count = 3;
  out.buttons = status_.buttons;
  out.has_sensed_force = 0;
  if (sequence_ != before) {
    for (int i = 0; i < 3; ++i) hip_[i] = encoder_to_hip_angle(options_.drive, status_.encoder[i]);
    Vec3 x{};
    if (forward_kinematics(options_.geometry, hip_, position_, x)) position_ = x;
  }
  out.sequence = sequence_;
  for (int i = 0; i < 3; ++i) {
    out.joint_rad[i] = hip_[i];
    out.position_m[i] = position_[i];
  }
}

void FalconDevice::write(const DeviceCommand& command) noexcept {
  if (handle_ == nullptr || out_flight_ || disconnected_) return;  // one frame in flight at a time
  Vec3 torque{};
  if (command.space == CommandSpace::kTaskForce)
    torques_for_force(options_.geometry, position_, {command.force_n[0], command.force_n[1], command.force_n[2]},
                      options_.max_torque_nm, torque);
  for (int i = 0; i < 3; ++i) command_.motor[i] = torque_to_command(options_.drive, torque[i]);
  command_.leds = kLedGreen;
  const Frame frame = encode_command(command_);
  std::memcpy(out_buffer_, frame.data(), kFrameSize);
  if (libusb_submit_transfer(out_) == 0) out_flight_ = true;
}

void FalconDevice::home() {
  if (handle_ == nullptr) throw DeviceError("falcon: home() before open()");
  // Homing mode: the firmware zeroes each encoder at its index mark while the user moves
  // the grip all the way out and back in (libnifalcon FalconFirmware.h, "Homing Mode").
  command_.homing = true;
  command_.leds = kLedBlue;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(options_.homing_timeout_s);
  while ((status_.homed & 0x7) != 0x7) {
    if (std::chrono::steady_clock::now() > deadline || disconnected_)
      throw DeviceError("falcon: homing did not finish; move the grip fully out and back in while homing");
    if (!out_flight_) {
      const Frame frame = encode_command(command_);
      std::memcpy(out_buffer_, frame.data(), kFrameSize);
      if (libusb_submit_transfer(out_) == 0) out_flight_ = true;
    }
    poll_events();
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  command_.homing = false;
}

void FalconDevice::close() noexcept {
  for (libusb_transfer* t : {in_, out_})
    if (t != nullptr) libusb_cancel_transfer(t);
  for (int i = 0; i < 100 && (in_flight_ || out_flight_) && context_ != nullptr; ++i) {
    timeval tv{0, 10000};
    libusb_handle_events_timeout_completed(context_, &tv, nullptr);
  }
  if (in_ != nullptr) libusb_free_transfer(in_);
  if (out_ != nullptr) libusb_free_transfer(out_);
  in_ = out_ = nullptr;
  in_flight_ = out_flight_ = false;
  if (handle_ != nullptr) {
    libusb_release_interface(handle_, 0);
    libusb_close(handle_);
    handle_ = nullptr;
  }
  if (context_ != nullptr) libusb_exit(context_);
  context_ = nullptr;
  disconnected_ = false;
}

}  // namespace needle::haptics::falcon
