#include "haptics/devices/falcon/falcon_protocol.hpp"

namespace needle::haptics::falcon {
namespace {

constexpr uint8_t kNibbleBase = 0x41;

void put_int16(uint8_t* at, int16_t value) {
  const auto bits = static_cast<uint16_t>(value);
  for (int i = 0; i < 4; ++i) at[i] = static_cast<uint8_t>(kNibbleBase + ((bits >> (4 * i)) & 0xF));
}

bool get_int16(const uint8_t* at, int16_t& value) {
  uint16_t bits = 0;
  for (int i = 0; i < 4; ++i) {
    if (at[i] < kNibbleBase || at[i] > kNibbleBase + 0xF) return false;
    bits = static_cast<uint16_t>(bits | ((at[i] - kNibbleBase) << (4 * i)));
  }
  value = static_cast<int16_t>(bits);
  return true;
}

}  // namespace

Frame encode_command(const MotorCommand& command) {
  Frame f{};
  f[0] = '<';
  for (int m = 0; m < 3; ++m) put_int16(&f[1 + 4 * m], command.motor[m]);
  f[13] = static_cast<uint8_t>(kNibbleBase + ((command.leds & 0x0E) | (command.homing ? 0x01 : 0x00)));
  f[14] = kNibbleBase;
  f[15] = '>';
  return f;
}

bool decode_status(const Frame& frame, DeviceStatus& status) {
  if (frame[0] != '<' || frame[15] != '>' || frame[13] < kNibbleBase) return false;
  DeviceStatus s;
  for (int m = 0; m < 3; ++m)
    if (!get_int16(&frame[1 + 4 * m], s.encoder[m])) return false;
  const auto flags = static_cast<uint8_t>(frame[13] - kNibbleBase);
  s.homed = (flags >> 4) & 0x7;
  s.buttons = flags & 0xF;
  status = s;
  return true;
}

int FrameAssembler::feed(const uint8_t* bytes, std::size_t count, DeviceStatus& latest) {
  int decoded = 0;
  for (std::size_t i = 0; i < count; ++i) {
    const uint8_t b = bytes[i];
    if (filled_ == 0 && b != '<') continue;  // resynchronise on the frame start
    pending_[filled_++] = b;
    if (filled_ < kFrameSize) continue;
    filled_ = 0;
    if (decode_status(pending_, latest)) {
      ++decoded;
    } else {
      ++rejected_;
    }
  }
  return decoded;
}

std::size_t strip_ftdi_status(const uint8_t* in, std::size_t count, uint8_t* out, std::size_t max_packet) {
  std::size_t written = 0;
  for (std::size_t start = 0; start < count; start += max_packet) {
    const std::size_t end = start + max_packet < count ? start + max_packet : count;
    for (std::size_t i = start + 2; i < end; ++i) out[written++] = in[i];
  }
  return written;
}

}  // namespace needle::haptics::falcon
