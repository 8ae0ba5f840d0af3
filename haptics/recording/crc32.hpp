// CRC-32 (IEEE 802.3, the polynomial of zip and PNG), the recording's checksum of its header and
// of each block of records. Any damage of up to 32 bits in a row, and all but 1 in 2^32 of any
// other damage, changes it.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>

namespace needle::haptics {

namespace crc32_detail {
constexpr std::array<uint32_t, 256> table() {
  std::array<uint32_t, 256> t{};
  for (uint32_t n = 0; n < 256; ++n) {
    uint32_t c = n;
    for (int k = 0; k < 8; ++k) c = (c & 1u) ? 0xEDB88320u ^ (c >> 1) : c >> 1;
    t[n] = c;
  }
  return t;
}
inline constexpr std::array<uint32_t, 256> kTable = table();
}  // namespace crc32_detail

// The CRC of `size` bytes following `crc`, the CRC of what came before them (0 for none).
inline uint32_t crc32(const void* data, std::size_t size, uint32_t crc = 0) noexcept {
  const auto* p = static_cast<const uint8_t*>(data);
  crc = ~crc;
  for (std::size_t i = 0; i < size; ++i) crc = crc32_detail::kTable[(crc ^ p[i]) & 0xFFu] ^ (crc >> 8);
  return ~crc;
}

}  // namespace needle::haptics
