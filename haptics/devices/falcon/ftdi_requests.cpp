#include "haptics/devices/falcon/ftdi_requests.hpp"

#include <cmath>
#include <initializer_list>

namespace needle::haptics::falcon::ftdi {

BaudSetting baud_setting(double baud) {
  constexpr double kClock = 3'000'000.0;
  constexpr uint32_t kFractionCode[8] = {0, 3, 2, 4, 1, 5, 6, 7};
  // Candidates in eighths of the divisor: the special 8 (3 Mbaud) and 12 (2 Mbaud), and the
  // two regular divisors around the ideal one.
  const double ideal = 8.0 * kClock / baud;
  const auto floor8 = static_cast<long>(std::floor(ideal));
  BaudSetting best;
  double best_error = -1.0;
  for (long eighths : {8L, 12L, floor8, floor8 + 1}) {
    if (eighths != 8 && eighths != 12 && (eighths < 16 || eighths > 16383 * 8 + 7)) continue;
    const double actual = 8.0 * kClock / static_cast<double>(eighths);
    const double error = std::abs(actual - baud);
    if (best_error >= 0.0 && error >= best_error) continue;
    best_error = error;
    uint32_t encoded = 0;
    if (eighths == 8) {
      encoded = 0;
    } else if (eighths == 12) {
      encoded = 1;
    } else {
      encoded = static_cast<uint32_t>(eighths >> 3) | (kFractionCode[eighths & 7] << 14);
    }
    best = {static_cast<uint16_t>(encoded & 0xFFFF), static_cast<uint16_t>(encoded >> 16), actual};
  }
  return best;
}

}  // namespace needle::haptics::falcon::ftdi
