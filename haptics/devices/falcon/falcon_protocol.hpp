// The Novint Falcon's normal-mode wire protocol (firmware from Novint's SDK), as
// documented by libnifalcon (src/firmware/FalconFirmwareNovintSDK.cpp): fixed 16-byte
// frames '<' ... '>' in both directions, every payload nibble sent as the byte 0x41 + nibble.
//   host -> device: 3 x int16 motor commands (4 nibbles each, least significant first),
//                   byte 13 = LED bits | homing-mode bit 0x01, byte 14 = 0.
//   device -> host: 3 x int16 encoder counts (same layout), byte 13 = homed bits (one per
//                   motor) << 4 | grip buttons; byte 14 unused.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>

namespace needle::haptics::falcon {

inline constexpr uint16_t kVendorId = 0x0403;   // FTDI
inline constexpr uint16_t kProductId = 0xCB48;  // Novint Falcon
inline constexpr std::size_t kFrameSize = 16;

using Frame = std::array<uint8_t, kFrameSize>;

enum Led : uint8_t { kLedGreen = 0x2, kLedBlue = 0x4, kLedRed = 0x8 };

struct MotorCommand {
  std::array<int16_t, 3> motor{};
  uint8_t leds = 0;
  bool homing = false;
};

struct DeviceStatus {
  std::array<int16_t, 3> encoder{};
  uint8_t homed = 0;    // bit i: motor i homed
  uint8_t buttons = 0;  // grip buttons, 4 bits
};

Frame encode_command(const MotorCommand& command);
// False (status untouched) when the frame is not '<' ... '>' or a nibble byte is out of range.
bool decode_status(const Frame& frame, DeviceStatus& status);

// Reassembles frames from the byte stream (USB reads split and merge frames freely).
// Fixed storage, no allocation: bytes beyond what can form a frame are dropped while
// resynchronising on '<'.
class FrameAssembler {
 public:
  // Feeds bytes; every complete frame that decodes is written to `latest` (the newest wins).
  // Returns how many frames decoded.
  int feed(const uint8_t* bytes, std::size_t count, DeviceStatus& latest);
  uint64_t rejected() const { return rejected_; }

 private:
  Frame pending_{};
  std::size_t filled_ = 0;
  uint64_t rejected_ = 0;
};

// An FTDI chip prefixes every USB packet it sends (max_packet bytes, 64 at full speed) with
// two modem-status bytes. Copies the payload of `count` received bytes to `out` (which may
// equal `in`); returns the payload length.
std::size_t strip_ftdi_status(const uint8_t* in, std::size_t count, uint8_t* out, std::size_t max_packet = 64);

}  // namespace needle::haptics::falcon
