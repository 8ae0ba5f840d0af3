#include <gtest/gtest.h>

#include <cstring>
#include <string>

#include "haptics/devices/falcon/falcon_protocol.hpp"
#include "haptics/devices/falcon/ftdi_requests.hpp"

namespace needle::haptics::falcon {
namespace {

Frame frame_of(const std::string& text) {
  Frame f{};
  EXPECT_EQ(text.size(), kFrameSize);
  std::memcpy(f.data(), text.data(), kFrameSize);
  return f;
}

TEST(FalconCodec, CommandFrameMatchesTheHandEncodedBytes) {
  MotorCommand c;
  c.motor = {0x1234, -1, 0};
  c.leds = kLedRed;
  c.homing = true;
  // 0x1234 least significant nibble first: 4 3 2 1 -> 'E' 'D' 'C' 'B'; -1 = 0xFFFF -> 'P' x 4;
  // 0 -> 'A' x 4; byte 13: red 0x8 | homing 0x1 = 0x9 -> 'J'; byte 14: 0 -> 'A'.
  const Frame f = encode_command(c);
  EXPECT_EQ(std::string(f.begin(), f.end()), "<EDCBPPPPAAAAJA>");
}

TEST(FalconCodec, StatusFrameDecodesEncodersHomingAndButtons) {
  // Byte 13 = 0x41 + (homed 0b111 << 4 | buttons 0b0010) = 0x41 + 0x72 = 0xB3.
  std::string text = "<EDCBPPPPAAAA";
  text += static_cast<char>(0xB3);
  text += "A>";
  DeviceStatus s;
  ASSERT_TRUE(decode_status(frame_of(text), s));
  EXPECT_EQ(s.encoder[0], 0x1234);
  EXPECT_EQ(s.encoder[1], -1);
  EXPECT_EQ(s.encoder[2], 0);
  EXPECT_EQ(s.homed, 7);
  EXPECT_EQ(s.buttons, 2);
}

TEST(FalconCodec, EveryInt16SurvivesTheNibbleEncoding) {
  for (int v = -32768; v <= 32767; v += 97) {
    MotorCommand c;
    c.motor = {static_cast<int16_t>(v), static_cast<int16_t>(-v - 1), static_cast<int16_t>(v / 3)};
    // The command frame has the same layout as a status frame with no flags set.
    DeviceStatus s;
    ASSERT_TRUE(decode_status(encode_command(c), s));
    EXPECT_EQ(s.encoder, c.motor) << v;
  }
}

TEST(FalconCodec, MalformedFramesAreRejected) {
  DeviceStatus s;
  EXPECT_FALSE(decode_status(frame_of("XEDCBPPPPAAAAAA>"), s));
  EXPECT_FALSE(decode_status(frame_of("<EDCBPPPPAAAAAA<"), s));
  EXPECT_FALSE(decode_status(frame_of("<E@CBPPPPAAAAAA>"), s)) << "0x40 is below the nibble base";
  EXPECT_FALSE(decode_status(frame_of("<EDCBPPPQAAAAAA>"), s)) << "'Q' is nibble 16";
}

TEST(FalconCodec, AssemblerFindsFramesSplitAcrossReadsAfterGarbage) {
  const std::string one = "<BAAAAAAAAAAAAA>";  // encoder 0 = 1
  const std::string two = "<CAAAAAAAAAAAAA>";  // encoder 0 = 2
  const std::string stream = "xy>" + one + two;
  FrameAssembler assembler;
  DeviceStatus latest;
  const auto* bytes = reinterpret_cast<const uint8_t*>(stream.data());
  EXPECT_EQ(assembler.feed(bytes, 10, latest), 0);
  EXPECT_EQ(assembler.feed(bytes + 10, 12, latest), 1);
  EXPECT_EQ(latest.encoder[0], 1);
  EXPECT_EQ(assembler.feed(bytes + 22, stream.size() - 22, latest), 1);
  EXPECT_EQ(latest.encoder[0], 2);
  EXPECT_EQ(assembler.rejected(), 0u);
}

TEST(FalconCodec, FtdiStatusBytesAreStrippedFromEveryUsbPacket) {
  // 64 + 64 + 5 received bytes: each packet starts with 2 status bytes (0xFF here).
  uint8_t in[133];
  for (std::size_t i = 0; i < sizeof in; ++i) in[i] = (i % 64 < 2) ? 0xFF : static_cast<uint8_t>(i);
  uint8_t out[133];
  const std::size_t n = strip_ftdi_status(in, sizeof in, out);
  ASSERT_EQ(n, 62u + 62u + 3u);
  EXPECT_EQ(out[0], 2);
  EXPECT_EQ(out[61], 63);
  EXPECT_EQ(out[62], 66);
  EXPECT_EQ(out[124], 130);
  for (std::size_t i = 0; i < n; ++i) EXPECT_NE(out[i], 0xFF);
}

// Divisors by hand: 3 MHz / baud in eighths, the fraction coded 0,3,2,4,1,5,6,7 (AN232B-05).
TEST(FalconFtdi, BaudDivisorsOfTheFalconsThreeRates) {
  // 9600: 312.5 = 312 + 4/8 -> 312 | code(4) = 1 << 14 = 0x4138 (libnifalcon uses 0x4138).
  auto b = ftdi::baud_setting(9600);
  EXPECT_EQ(b.value, 0x4138);
  EXPECT_EQ(b.index, 0);
  EXPECT_DOUBLE_EQ(b.actual_baud, 9600.0);
  // 1456312: 2.060 -> nearest 2 + 0/8 (1.5 Mbaud) = 0x0002 (libnifalcon's normal-mode value).
  b = ftdi::baud_setting(1456312);
  EXPECT_EQ(b.value, 0x0002);
  EXPECT_EQ(b.index, 0);
  // 140000: 21.43 -> 21 + 3/8, code(3) = 4 = 0b100: bit 2 goes to wIndex.
  b = ftdi::baud_setting(140000);
  EXPECT_EQ(b.value, 0x0015);
  EXPECT_EQ(b.index, 1);
  EXPECT_NEAR(b.actual_baud, 3e6 / 21.375, 1e-6);
  EXPECT_EQ(ftdi::baud_setting(3e6).value, 0);
  EXPECT_EQ(ftdi::baud_setting(2e6).value, 1);
}

}  // namespace
}  // namespace needle::haptics::falcon
