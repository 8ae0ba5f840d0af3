// The structure that found the readers' faults, as mutations a fuzz target applies besides
// libFuzzer's own byte-level ones (tests/README.md, "Sanitizers and fuzzing"): a number replaced
// by an extreme one (1e300, 1e-300, -1e300, 1e999, a count of 2^32), a value wrapped in arrays or
// elements nested past every reader's depth limit, and in a recording, a reading overwritten with
// NaN or 1e300 under checksums made valid again, so the input passes the bytes' checks and reaches
// the content's. Random bytes alone reach none of these: a digit at a time never makes 1e300, and
// any change to a recording's records fails its checksum.
//
// Each mutation takes the input in `data` (`size` bytes, room for `max_size`) and returns its new
// size, or 0 when it does not apply (no number in the input, no room, not a recording): the target
// then falls back to libFuzzer's mutations. Header-only, without libFuzzer: the tests check the
// mutations themselves (tests/io/test_fuzz_structure.cpp, tests/haptics/test_recording_integrity.cpp).
#pragma once

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <initializer_list>
#include <limits>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "haptics/recording/crc32.hpp"
#include "haptics/recording/session_format.hpp"

namespace needle::fuzz {

// Numbers that have broken readers: past every physical range, below every tolerance, overflowing
// a double (1e999 parses to infinity), a float (1e39), a 32-bit count (4294967296), or zero.
inline constexpr std::array<const char*, 11> kExtremeNumbers = {
    "1e300", "-1e300", "1e-300", "1e999", "1e308", "1e39", "4294967296", "-1", "0", "1e6", "5e-324"};

// Where the numbers of a text are: [begin, end) of each run of characters a number is written in.
inline std::vector<std::pair<size_t, size_t>> number_spans(const std::string& text) {
  std::vector<std::pair<size_t, size_t>> spans;
  auto starts = [](char c) { return (c >= '0' && c <= '9') || c == '-'; };
  auto continues = [](char c) {
    return (c >= '0' && c <= '9') || c == '-' || c == '+' || c == '.' || c == 'e' || c == 'E';
  };
  for (size_t i = 0; i < text.size();) {
    if (!starts(text[i]) || (i > 0 && (std::isalnum(static_cast<unsigned char>(text[i - 1])) || text[i - 1] == '_'))) {
      ++i;
      continue;
    }
    size_t j = i + 1;
    while (j < text.size() && continues(text[j])) ++j;
    spans.emplace_back(i, j);
    i = j;
  }
  return spans;
}

// Replaces [begin, end) of the input by `text`; 0 when it would not fit in max_size.
inline size_t replace_span(uint8_t* data, size_t size, size_t max_size, size_t begin, size_t end,
                           const std::string& text) {
  const size_t new_size = size - (end - begin) + text.size();
  if (new_size > max_size) return 0;
  std::memmove(data + begin + text.size(), data + end, size - end);
  std::memcpy(data + begin, text.data(), text.size());
  return new_size;
}

inline std::string as_text(const uint8_t* data, size_t size) {
  return std::string(reinterpret_cast<const char*>(data), size);
}

// A number of a JSON or XML text (a key's value, an attribute's) replaced by one of kExtremeNumbers.
inline size_t extreme_number(uint8_t* data, size_t size, size_t max_size, std::mt19937& random) {
  const auto spans = number_spans(as_text(data, size));
  if (spans.empty()) return 0;
  const auto [begin, end] = spans[random() % spans.size()];
  return replace_span(data, size, max_size, begin, end, kExtremeNumbers[random() % kExtremeNumbers.size()]);
}

// How deep a nesting mutation goes: just past the readers' limit (io::kMaxNestingDepth, 64), or
// far past it, where an unbounded reader's recursion overflows the stack.
inline size_t nesting_depth(std::mt19937& random) {
  constexpr size_t kDepths[] = {65, 300, 20000};
  return kDepths[random() % std::size(kDepths)];
}

// A number of a JSON text wrapped in arrays nested nesting_depth() deep: [[[...[1e300]...]]].
inline size_t deep_json(uint8_t* data, size_t size, size_t max_size, std::mt19937& random) {
  const auto spans = number_spans(as_text(data, size));
  if (spans.empty()) return 0;
  const auto [begin, end] = spans[random() % spans.size()];
  const size_t depth = nesting_depth(random);
  return replace_span(data, size, max_size, begin, end,
                      std::string(depth, '[') + as_text(data + begin, end - begin) + std::string(depth, ']'));
}

// Elements nested nesting_depth() deep, <a><a>...</a></a>, put after the first element's start tag.
inline size_t deep_xml(uint8_t* data, size_t size, size_t max_size, std::mt19937& random) {
  const std::string text = as_text(data, size);
  size_t at = text.find("<robot");
  if (at == std::string::npos) at = text.find('<');
  at = text.find('>', at == std::string::npos ? 0 : at);
  if (at == std::string::npos) return 0;
  const size_t depth = nesting_depth(random);
  std::string nest;
  for (size_t k = 0; k < depth; ++k) nest += "<link>";
  for (size_t k = 0; k < depth; ++k) nest += "</link>";
  return replace_span(data, size, max_size, at + 1, at + 1, nest);
}

// A value of a checksummed (format 3) recording's records overwritten, the block's checksums made
// valid again: a double with NaN, an infinity, 1e300 or -1e300, or a 32-bit count with 2^31.
// 0 when the input is not a recording with a whole block.
inline size_t extreme_record_value(uint8_t* data, size_t size, size_t, std::mt19937& random) {
  auto u32 = [&](size_t at) {
    uint32_t v;
    std::memcpy(&v, data + at, 4);
    return v;
  };
  if (size < 24 || std::memcmp(data, "NEEDLREC", 8) != 0 || u32(8) != 3) return 0;
  const size_t header_bytes = u32(12), record_bytes = u32(20);
  if (record_bytes < 8 || record_bytes > 4096 || header_bytes > size) return 0;
  // The blocks: their offsets, whole ones only.
  std::vector<size_t> blocks;
  for (size_t at = header_bytes; at + haptics::kBlockHeaderBytes <= size && std::memcmp(data + at, "NBLK", 4) == 0;) {
    const size_t records = size_t(u32(at + 12)) * record_bytes;
    if (records == 0 || at + haptics::kBlockHeaderBytes + records > size) break;
    blocks.push_back(at);
    at += haptics::kBlockHeaderBytes + records;
  }
  if (blocks.empty()) return 0;
  const size_t block = blocks[random() % blocks.size()];
  const uint32_t count = u32(block + 12);
  uint8_t* records = data + block + haptics::kBlockHeaderBytes;
  // Any 4-byte-aligned place of one record: a double's or a count's.
  const size_t at = size_t(random() % count) * record_bytes + (random() % (record_bytes / 4)) * 4;
  if (random() % 4 == 0) {
    const uint32_t count_value = 1u << 31;
    std::memcpy(records + at, &count_value, 4);
  } else if (at + 8 <= size_t(count) * record_bytes) {
    const double values[] = {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity(), 1e300,
                             -1e300};
    std::memcpy(records + at, &values[random() % std::size(values)], 8);
  }
  const uint32_t records_crc = haptics::crc32(records, size_t(count) * record_bytes);
  std::memcpy(data + block + 16, &records_crc, 4);
  const uint32_t header_crc = haptics::crc32(data + block, 20);
  std::memcpy(data + block + 20, &header_crc, 4);
  return size;
}

}  // namespace needle::fuzz

#ifdef NEEDLE_LIBFUZZER
extern "C" size_t LLVMFuzzerMutate(uint8_t* data, size_t size, size_t max_size);

namespace needle::fuzz {

using Mutation = size_t (*)(uint8_t* data, size_t size, size_t max_size, std::mt19937& random);

// A target's custom mutation: one of its structured `mutations` half the time, libFuzzer's own
// the other half, or when the one chosen does not apply.
inline size_t mutate(uint8_t* data, size_t size, size_t max_size, unsigned seed,
                     std::initializer_list<Mutation> mutations) {
  std::mt19937 random(seed);
  if (random() % 2 == 0)
    if (const size_t n = (*(mutations.begin() + random() % mutations.size()))(data, size, max_size, random)) return n;
  return LLVMFuzzerMutate(data, size, max_size);
}

}  // namespace needle::fuzz

// Defines the target's LLVMFuzzerCustomMutator with these mutations.
#define NEEDLE_FUZZ_MUTATIONS(...)                                                                        \
  extern "C" size_t LLVMFuzzerCustomMutator(uint8_t* data, size_t size, size_t max_size, unsigned seed) { \
    return needle::fuzz::mutate(data, size, max_size, seed, {__VA_ARGS__});                               \
  }
#else
// Without libFuzzer (replay_main.cpp runs each input once) there is nothing to mutate.
#define NEEDLE_FUZZ_MUTATIONS(...)
#endif
