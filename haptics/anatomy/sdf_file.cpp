#include "haptics/anatomy/sdf_file.hpp"

#include <algorithm>
#include <bit>
#include <cstring>

#include "io/file_read.hpp"
#include "io/file_write.hpp"

namespace needle::haptics::anatomy {
namespace {

static_assert(std::endian::native == std::endian::little, "the NSDF format is little-endian, as this machine");

constexpr char kMagic[4] = {'N', 'S', 'D', 'F'};
constexpr uint32_t kVersion = 1;
constexpr size_t kHeaderBytes = 4 + 4 + 3 * 4 + 3 * 8 + 8 + 8;

template <class T>
void put(std::string& out, T value) {
  out.append(reinterpret_cast<const char*>(&value), sizeof value);
}

template <class T>
T get(const std::string& in, size_t& at) {
  T value;
  std::memcpy(&value, in.data() + at, sizeof value);
  at += sizeof value;
  return value;
}

}  // namespace

std::string sdf_file_bytes(const SdfGrid& grid) {
  std::string out(kMagic, 4);
  put(out, kVersion);
  for (int n : grid.nodes()) put(out, uint32_t(n));
  for (int a = 0; a < 3; ++a) put(out, grid.origin()[a]);
  put(out, grid.spacing());
  put(out, grid.quantum());
  out.append(reinterpret_cast<const char*>(grid.values().data()), grid.bytes());
  return out;
}

void write_sdf_file(const std::string& path, const SdfGrid& grid) { io::write_file(path, sdf_file_bytes(grid)); }

SdfGrid read_sdf_file(const std::string& path) {
  std::string problem;
  const std::string bytes =
      io::read_bytes(path, kHeaderBytes + uint64_t(SdfGrid::kMaxNodes) * sizeof(int16_t), problem);
  if (!problem.empty()) throw SdfFileError(path + ": " + problem);
  if (bytes.size() < kHeaderBytes || std::memcmp(bytes.data(), kMagic, 4) != 0)
    throw SdfFileError(path + ": not a signed distance grid (no NSDF header)");
  size_t at = 4;
  const uint32_t version = get<uint32_t>(bytes, at);
  if (version != kVersion)
    throw SdfFileError(path + ": NSDF version " + std::to_string(version) + ", this build reads 1");
  std::array<int, 3> nodes{};
  uint64_t count = 1;
  for (int& n : nodes) {
    const uint32_t v = get<uint32_t>(bytes, at);
    n = int(std::min<uint32_t>(v, 1u << 30));
    count *= v;
  }
  Eigen::Vector3d origin;
  for (int a = 0; a < 3; ++a) origin[a] = get<double>(bytes, at);
  const double spacing = get<double>(bytes, at), quantum = get<double>(bytes, at);
  if (count > uint64_t(SdfGrid::kMaxNodes))
    throw SdfFileError(path + ": nodes: at most " + std::to_string(SdfGrid::kMaxNodes) + " in all, the header says " +
                       std::to_string(count));
  const uint64_t expected = kHeaderBytes + count * sizeof(int16_t);
  if (bytes.size() != expected)
    throw SdfFileError(path + ": " + std::to_string(bytes.size()) + " bytes, its node counts need " +
                       std::to_string(expected) + (bytes.size() < expected ? " (cut short)" : " (extra bytes)"));
  std::vector<int16_t> values(count);
  std::memcpy(values.data(), bytes.data() + kHeaderBytes, count * sizeof(int16_t));
  try {
    return SdfGrid(origin, spacing, nodes, quantum, std::move(values));
  } catch (const SdfGridError& e) {
    throw SdfFileError(path + ": " + e.what());
  }
}

}  // namespace needle::haptics::anatomy
