// FTDI FT232 vendor control requests, the subset the Falcon needs (libftdi's ftdi.h and
// FTDI application note AN232B-05 document them): bmRequestType 0x40 (vendor, device,
// host to device), wValue and wIndex per request.
#pragma once

#include <cstdint>

namespace needle::haptics::falcon::ftdi {

inline constexpr uint8_t kRequestTypeOut = 0x40;
inline constexpr uint8_t kEndpointIn = 0x81;
inline constexpr uint8_t kEndpointOut = 0x02;

inline constexpr uint8_t kReset = 0x00;      // wValue: 0 reset, 1 purge RX, 2 purge TX
inline constexpr uint8_t kModemCtrl = 0x01;  // wValue: (mask << 8) | level
inline constexpr uint8_t kSetFlowCtrl = 0x02;
inline constexpr uint8_t kSetBaudRate = 0x03;
inline constexpr uint8_t kSetData = 0x04;  // wValue: bits | parity << 8 | stop << 11
inline constexpr uint8_t kSetLatencyTimer = 0x09;

inline constexpr uint16_t kResetSio = 0, kPurgeRx = 1, kPurgeTx = 2;
inline constexpr uint16_t kDtrHigh = 0x0101, kDtrLow = 0x0100, kRtsHigh = 0x0202, kRtsLow = 0x0200;
inline constexpr uint16_t kLine8N1 = 0x0008;
inline constexpr uint16_t kNoFlowControl = 0x0000;

struct BaudSetting {
  uint16_t value = 0;  // wValue
  uint16_t index = 0;  // wIndex (high bit of the fraction on single-port chips)
  double actual_baud = 0.0;
};

// The FT232BM divisor for a baud rate: 3 MHz / (n + k/8), n in [2, 16383], with 3 Mbaud
// and 2 Mbaud as the special divisors 0 and 1. The eighths are coded 0, 3, 2, 4, 1, 5, 6, 7
// (AN232B-05); the code's bit 2 goes to wIndex. The nearest achievable rate wins.
BaudSetting baud_setting(double baud);

}  // namespace needle::haptics::falcon::ftdi
