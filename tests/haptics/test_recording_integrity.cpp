// The recording's integrity (haptics/recording/session_format.hpp): damage anywhere is an error
// naming the file and the byte offset, never other data; a cut file reads up to its last whole
// block and says where; what is not a recording is refused before anything is read; older
// versions still read and say what they lack. Offsets are computed from the format's own layout.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <random>

#include "haptics/devices/replay_device.hpp"
#include "haptics/recording/crc32.hpp"
#include "haptics/recording/session_recorder.hpp"
#include "tests/fuzz/structure.hpp"

namespace needle::haptics {
namespace {

namespace fs = std::filesystem;

std::string temp_path(const std::string& name) {
  return (fs::temp_directory_path() / ("needle_integrity_" + std::to_string(::getpid()) + "_" + name)).string();
}

std::vector<uint8_t> file_bytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

void write_bytes(const std::string& path, const std::vector<uint8_t>& bytes) {
  std::ofstream(path, std::ios::binary)
      .write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
}

const SessionHeader kHeader{kSessionFormatVersion, 1000.0, 1700000000, "sim", R"({"task": "t.json"})"};

TickSample sample(uint64_t k) {
  TickSample s;
  s.tick = k;
  s.time_ns = int64_t(k) * 1000000;
  s.reading.sequence = k;
  s.reading.position_m[0] = 1e-6 * double(k);
  s.state.time_s = 0.001 * double(k);
  return s;
}

// A recording of `ticks` samples drained in one pass, so its blocks hold 256 records but the last.
void record(const std::string& path, uint64_t ticks, bool ran_to_end = true) {
  SpscRing<TickSample> ring(4096);
  SessionRecorder recorder(path, kHeader, ring);
  for (uint64_t k = 0; k < ticks; ++k) ring.push(sample(k));
  recorder.drain();
  recorder.stop(ran_to_end);
  ASSERT_EQ(recorder.error(), "");
}

// A recording of `ticks` ticks as record() makes it, and its bytes.
std::vector<uint8_t> recorded(const std::string& path, uint64_t ticks) {
  record(path, ticks);
  return file_bytes(path);
}

// Byte offset of block `k` in a recording made by record().
uint64_t block_offset(int k) {
  return encode_header(kHeader).size() + uint64_t(k) * (kBlockHeaderBytes + 256 * session_record_bytes());
}

std::string error_of(const std::string& path) {
  try {
    read_session(path);
  } catch (const RecordingError& e) {
    return e.what();
  }
  return "";
}

TEST(RecordingIntegrity, AClosedRecordingReadsWholeWithItsEndMark) {
  const std::string path = temp_path("closed.nrec");
  record(path, 1000);
  EXPECT_EQ(fs::file_size(path), block_offset(3) + kBlockHeaderBytes + 232 * session_record_bytes() + kEndBytes);
  const Session s = read_session(path);
  ASSERT_EQ(s.records.size(), 1000u);
  for (uint64_t k = 0; k < 1000; ++k) ASSERT_EQ(s.records[k].reading.position_m[0], 1e-6 * double(k));
  EXPECT_TRUE(s.end.checksummed);
  EXPECT_TRUE(s.end.closed);
  EXPECT_TRUE(s.end.ran_to_end);
  EXPECT_EQ(s.end.whole_bytes, fs::file_size(path));
  EXPECT_TRUE(recording_notes(path, s.end, s.records.size()).empty());
  EXPECT_EQ(s.header.device, kHeader.device);
  EXPECT_EQ(s.header.context, kHeader.context);
  EXPECT_EQ(s.header.rate_hz, kHeader.rate_hz);

  record(path, 10, /*ran_to_end=*/false);  // a window closed before the task ended
  EXPECT_TRUE(read_session(path).end.closed);
  EXPECT_FALSE(read_session(path).end.ran_to_end);
  fs::remove(path);
}

TEST(RecordingIntegrity, DamageToABlockIsAnErrorNamingTheFileAndTheByteOffset) {
  const std::string path = temp_path("damaged.nrec");
  const std::vector<uint8_t> good = recorded(path, 1000);
  const uint64_t block = block_offset(1);
  const uint64_t record_300 = block + kBlockHeaderBytes + 44 * session_record_bytes();  // tick 300 is block 1's 45th
  const std::string expected =
      path + ": block at byte " + std::to_string(block) + ": records checksum mismatch (damaged)";

  std::vector<uint8_t> bad = good;  // a run of 0xFF bytes over the block's records
  std::fill(bad.begin() + long(record_300), bad.begin() + long(record_300 + 4096), 0xFF);
  write_bytes(path, bad);
  EXPECT_EQ(error_of(path), expected);

  bad = good;  // random bytes
  std::mt19937 random(11);
  for (uint64_t i = record_300; i < record_300 + 700; ++i) bad[i] = uint8_t(random());
  write_bytes(path, bad);
  EXPECT_EQ(error_of(path), expected);

  bad = good;  // a NaN in place of a recorded position: a well-formed number, a wrong record
  const double nan = std::nan("");
  TickSample s = sample(300);
  std::vector<uint8_t> one;
  encode_record(s, one);
  const uint64_t position_at =
      std::search(one.begin(), one.end(), reinterpret_cast<const uint8_t*>(&s.reading.position_m[0]),
                  reinterpret_cast<const uint8_t*>(&s.reading.position_m[0]) + 8) -
      one.begin();
  ASSERT_LT(position_at, one.size());
  std::memcpy(&bad[record_300 + position_at], &nan, 8);
  write_bytes(path, bad);
  EXPECT_EQ(error_of(path), expected);

  bad = good;  // one bit of a record
  bad[record_300 + 100] ^= 0x10;
  write_bytes(path, bad);
  EXPECT_EQ(error_of(path), expected);

  bad = good;  // the block's record count
  bad[block + 12] = 3;
  write_bytes(path, bad);
  EXPECT_EQ(error_of(path), path + ": block at byte " + std::to_string(block) + ": header checksum mismatch (damaged)");

  bad = good;  // the end mark's count
  bad[bad.size() - kEndBytes + 4] ^= 1;
  write_bytes(path, bad);
  EXPECT_EQ(error_of(path),
            path + ": end at byte " + std::to_string(good.size() - kEndBytes) + ": checksum mismatch (damaged)");

  // The replay device refuses it before its first tick.
  bad = good;
  bad[record_300 + 100] ^= 0x10;
  write_bytes(path, bad);
  ReplayDevice replay(path);
  try {
    replay.open();
    ADD_FAILURE() << "a damaged recording opened for replay";
  } catch (const RecordingError& e) {
    EXPECT_EQ(std::string(e.what()), expected);
  }
  fs::remove(path);
}

TEST(RecordingIntegrity, ABlockMissingOrRepeatedIsAnError) {
  const std::string path = temp_path("missing_block.nrec");
  const std::vector<uint8_t> good = recorded(path, 1000);
  std::vector<uint8_t> bad = good;
  bad.erase(bad.begin() + long(block_offset(1)), bad.begin() + long(block_offset(2)));
  write_bytes(path, bad);
  EXPECT_EQ(error_of(path), path + ": block at byte " + std::to_string(block_offset(1)) +
                                ": starts at tick 512, expected 256 (a block is missing or repeated)");
  bad = good;
  bad.insert(bad.begin() + long(block_offset(2)), good.begin() + long(block_offset(1)),
             good.begin() + long(block_offset(2)));
  write_bytes(path, bad);
  EXPECT_EQ(error_of(path), path + ": block at byte " + std::to_string(block_offset(2)) +
                                ": starts at tick 256, expected 512 (a block is missing or repeated)");
  fs::remove(path);
}

TEST(RecordingIntegrity, EditingTheHeaderIsAnError) {
  const std::string path = temp_path("header.nrec");
  const std::vector<uint8_t> good = recorded(path, 10);
  std::vector<uint8_t> bad = good;
  const double rate = 500.0;  // the rate, edited as a user would to replay at another speed
  std::memcpy(&bad[24], &rate, 8);
  write_bytes(path, bad);
  EXPECT_EQ(error_of(path), path + ": header: checksum mismatch: the header was changed or damaged");
  bad = good;
  bad[44] = 'S';  // the device name
  write_bytes(path, bad);
  EXPECT_EQ(error_of(path), path + ": header: checksum mismatch: the header was changed or damaged");
  fs::remove(path);
}

TEST(RecordingIntegrity, ACutFileReadsUpToItsLastWholeBlockAndSaysWhere) {
  const std::string path = temp_path("cut.nrec");
  const std::vector<uint8_t> good = recorded(path, 1000);
  const uint64_t cut_at = block_offset(2) + kBlockHeaderBytes + 100;  // in block 2's first record
  write_bytes(path, {good.begin(), good.begin() + long(cut_at)});
  Session s = read_session(path);
  ASSERT_EQ(s.records.size(), 512u);
  EXPECT_EQ(s.records.back().tick, 511u);
  EXPECT_FALSE(s.end.closed);
  EXPECT_EQ(s.end.whole_bytes, block_offset(2));
  EXPECT_EQ(s.end.trailing_bytes, kBlockHeaderBytes + 100);
  EXPECT_EQ(recording_notes(path, s.end, s.records.size()),
            std::vector<std::string>{path + ": cut at byte " + std::to_string(block_offset(2)) +
                                     " after 512 ticks (its run " +
                                     "stopped without closing it, 124 bytes of a last block lost): read up to there"});

  for (uint64_t cut : {uint64_t(good.size() - kEndBytes), uint64_t(good.size() - 5), block_offset(1) + 2}) {
    write_bytes(path, {good.begin(), good.begin() + long(cut)});
    s = read_session(path);
    EXPECT_FALSE(s.end.closed) << cut;
    EXPECT_EQ(s.records.size(), cut >= good.size() - kEndBytes ? 1000u : 256u) << cut;
  }

  write_bytes(path, {good.begin(), good.begin() + 30});  // inside the header
  EXPECT_EQ(error_of(path), path + ": header: truncated (the file has 30 bytes)");

  std::vector<uint8_t> longer = good;  // bytes after the end mark are not a cut: something wrote there
  longer.push_back(0);
  write_bytes(path, longer);
  EXPECT_EQ(error_of(path), path + ": end at byte " + std::to_string(good.size() - kEndBytes) +
                                ": 1 bytes after the end of the recording");
  fs::remove(path);
}

// Milliseconds `read_session(path)` takes to refuse `path`, its message in `error`.
double refusal_ms(const std::string& path, std::string& error) {
  const auto t0 = std::chrono::steady_clock::now();
  error = error_of(path);
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

TEST(RecordingIntegrity, WhatIsNotARecordingIsRefusedBeforeAnythingIsRead) {
  std::string error;
  EXPECT_LT(refusal_ms("/dev/zero", error), 100.0);
  EXPECT_EQ(error, "/dev/zero: not a regular file (a device or a pipe), not a recording");
  const std::string folder = temp_path("folder.nrec");
  fs::create_directories(folder);
  EXPECT_EQ(error_of(folder), folder + ": is a folder, not a recording");
  fs::remove(folder);
  EXPECT_EQ(error_of(folder), folder + ": cannot be opened: No such file or directory");

  // 2 GiB of zeros (a sparse file: no disk is used), then the same behind a valid header.
  const std::string big = temp_path("big.nrec");
  const uint64_t two_gib = uint64_t(1) << 31;
  {
    const int fd = ::open(big.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    ASSERT_GE(fd, 0);
    ASSERT_EQ(::ftruncate(fd, off_t(two_gib)), 0);
    ::close(fd);
  }
  EXPECT_LT(refusal_ms(big, error), 100.0);
  EXPECT_EQ(error, big + ": header: not a needle-sim session recording (expected magic NEEDLREC)");
  auto put_header = [&big](const SessionHeader& header) {
    const std::vector<uint8_t> head = encode_header(header);
    std::fstream f(big, std::ios::binary | std::ios::in | std::ios::out);
    f.write(reinterpret_cast<const char*>(head.data()), std::streamsize(head.size()));
    return head.size();
  };
  // At 1 kHz the longest session (30 min) holds fewer bytes than this: refused by its size alone.
  put_header(kHeader);
  ASSERT_GT(two_gib, 1800001 * (session_record_bytes() + kBlockHeaderBytes) + kEndBytes);
  EXPECT_LT(refusal_ms(big, error), 100.0);
  EXPECT_EQ(error, big + ": 2147483648 bytes: more than a session of at most 30 minutes at 1000 Hz can hold");
  // At 10 kHz it could be a session: refused at its first block, without reading further.
  SessionHeader fast = kHeader;
  fast.rate_hz = 10000.0;
  const size_t header_bytes = put_header(fast);
  EXPECT_LT(refusal_ms(big, error), 100.0);
  EXPECT_EQ(error, big + ": block at byte " + std::to_string(header_bytes) + ": not a block of records (damaged)");
  fs::remove(big);
}

// `bytes` as a header of version 1 or 2, written field by field as those builds did.
std::vector<uint8_t> old_header(uint32_t version, const std::string& device, const std::string* context) {
  std::vector<uint8_t> out = {'N', 'E', 'E', 'D', 'L', 'R', 'E', 'C'};
  auto put = [&out](const auto& value) {
    const auto* p = reinterpret_cast<const uint8_t*>(&value);
    out.insert(out.end(), p, p + sizeof value);
  };
  put(version), put(static_cast<uint32_t>(session_record_bytes(1))), put(500.0), put(int64_t{7});
  put(static_cast<uint32_t>(device.size()));
  out.insert(out.end(), device.begin(), device.end());
  if (context) {
    put(static_cast<uint32_t>(context->size()));
    out.insert(out.end(), context->begin(), context->end());
  }
  return out;
}

// A header the reader refuses closes the file it opened (the fuzzer found the leak: after some
// ten thousand refused inputs no file could be opened at all).
TEST(RecordingIntegrity, ARefusedFileIsClosed) {
  const std::string bad = temp_path("refused.nrec");
  write_bytes(bad, {'N', 'E', 'E', 'D', 'L', 'R', 'E', 'C', 3, 0, 0, 0, 0, 0});
  auto open_files = [] { return std::distance(fs::directory_iterator("/proc/self/fd"), fs::directory_iterator()); };
  const auto before = open_files();
  for (int i = 0; i < 200; ++i) EXPECT_NE(error_of(bad), "");
  EXPECT_EQ(open_files(), before);
}

TEST(RecordingIntegrity, OlderVersionsStillReadAndSayTheyHaveNoChecksums) {
  const std::string path = temp_path("old.nrec");
  std::vector<uint8_t> v1 = old_header(1, "sim", nullptr);
  encode_record(sample(9), v1, 1);
  write_bytes(path, v1);
  Session s = read_session(path);
  EXPECT_EQ(s.header.version, 1u);
  EXPECT_EQ(s.header.device, "sim");
  EXPECT_EQ(s.header.context, "");
  ASSERT_EQ(s.records.size(), 1u);
  EXPECT_EQ(s.records[0].tick, 9u);
  EXPECT_FALSE(s.end.checksummed);
  EXPECT_EQ(
      recording_notes(path, s.end, 1),
      std::vector<std::string>{path + ": an older format without checksums: damage to its records cannot be detected"});

  const std::string context = R"({"task": "t.json", "bytes": "\u00e9\n"})";
  std::vector<uint8_t> v2 = old_header(2, "sim", &context);
  for (uint64_t k = 0; k < 300; ++k) encode_record(sample(k), v2, 1);
  v2.resize(v2.size() - 7);  // a kill mid-record: the whole records read, the partial one is said
  write_bytes(path, v2);
  s = read_session(path);
  EXPECT_EQ(s.header.version, 2u);
  EXPECT_EQ(s.header.context, context);
  ASSERT_EQ(s.records.size(), 299u);
  EXPECT_EQ(s.records[298].reading.position_m[0], sample(298).reading.position_m[0]);
  EXPECT_EQ(s.end.trailing_bytes, session_record_bytes(1) - 7);
  EXPECT_EQ(recording_notes(path, s.end, 299).back(),
            path + ": " + std::to_string(session_record_bytes(1) - 7) + " bytes of a last record cut short, dropped");

  std::vector<uint8_t> huge = old_header(2, "sim", &context);  // a length that would allocate 4 GB
  const uint32_t length = 0xFFFFFFF0u;
  std::memcpy(&huge[huge.size() - context.size() - 4], &length, 4);
  write_bytes(path, huge);
  EXPECT_EQ(error_of(path), path + ": header: context of 4294967280 bytes (at most 16777216)");

  SessionHeader future = kHeader;
  std::vector<uint8_t> next = encode_header(future);
  next[8] = kSessionFormatVersion + 1;
  write_bytes(path, next);
  EXPECT_EQ(error_of(path), path + ": header: format version " + std::to_string(kSessionFormatVersion + 1) +
                                ", this build reads versions 1 to " + std::to_string(kSessionFormatVersion));
  fs::remove(path);
}

// A header with the 32-bit field at `offset` set to `value` and its checksum made right again:
// what a newer build, not damage, would write.
std::vector<uint8_t> header_with(uint32_t offset, uint32_t value) {
  std::vector<uint8_t> h = encode_header(kHeader);
  std::memcpy(&h[offset], &value, 4);
  const uint32_t crc = crc32(h.data(), h.size() - 4);
  std::memcpy(&h[h.size() - 4], &crc, 4);
  return h;
}

TEST(RecordingIntegrity, TheRecordSizeIsTheHeadersNotTheFramings) {
  const std::string path = temp_path("payload.nrec");
  write_bytes(path, header_with(16, kPayloadVersion + 1));
  EXPECT_EQ(error_of(path), path + ": header: payload version " + std::to_string(kPayloadVersion + 1) +
                                ", this build reads versions 1 to " + std::to_string(kPayloadVersion));
  const uint32_t bigger = uint32_t(session_record_bytes() + 8);
  write_bytes(path, header_with(20, bigger));
  EXPECT_EQ(error_of(path), path + ": header: record size " + std::to_string(bigger) + " bytes, expected " +
                                std::to_string(session_record_bytes()) + " for payload version " +
                                std::to_string(kPayloadVersion));
  fs::remove(path);
}

// A tick in layered tissue: every field of the tissue snapshot set to a value of its own.
TickSample layered_sample(uint64_t k) {
  TickSample s = sample(k);
  TissueSnapshot& t = s.state.tissue;
  t.tip_layer = int32_t(k % 5);
  t.punctured_layers = 0b10110u + uint32_t(k);
  t.surface_layer = 3;
  t.bone_layer = int32_t(k % 2) - 1;
  t.axial_force_N = 1.25 + 1e-3 * double(k);
  t.bone_force_n[0] = -0.5, t.bone_force_n[1] = 0.1, t.bone_force_n[2] = std::nextafter(2.0, 3.0);
  t.deflection_m = 3.5e-3;
  t.surface_point_m[0] = 0.01, t.surface_point_m[1] = -0.02, t.surface_point_m[2] = 1.0 / 3.0;
  return s;
}

bool same_bits(const TissueSnapshot& a, const TissueSnapshot& b) {
  static_assert(std::has_unique_object_representations_v<int32_t>);
  auto bits = [](const TissueSnapshot& t) {
    std::vector<uint8_t> out;
    auto put = [&out](const auto& value) {
      const auto* p = reinterpret_cast<const uint8_t*>(&value);
      out.insert(out.end(), p, p + sizeof value);
    };
    put(t.tip_layer), put(t.punctured_layers), put(t.surface_layer), put(t.bone_layer), put(t.axial_force_N);
    put(t.bone_force_n), put(t.deflection_m), put(t.surface_point_m);
    return out;
  };
  return bits(a) == bits(b);
}

// Payload 2 keeps the layered tissue at the needle, bit for bit, through the checked blocks.
TEST(RecordingIntegrity, TheLayeredTissueStateIsRecordedBitForBit) {
  const std::string path = temp_path("layered.nrec");
  {
    SpscRing<TickSample> ring(4096);
    SessionRecorder recorder(path, kHeader, ring);
    for (uint64_t k = 0; k < 300; ++k) ring.push(layered_sample(k));
    recorder.drain();
    recorder.stop(true);
    ASSERT_EQ(recorder.error(), "");
  }
  const Session s = read_session(path);
  EXPECT_EQ(s.header.payload_version, kPayloadVersion);
  ASSERT_EQ(s.records.size(), 300u);
  for (uint64_t k = 0; k < 300; ++k) {
    EXPECT_TRUE(same_bits(s.records[k].state.tissue, layered_sample(k).state.tissue)) << "tick " << k;
    EXPECT_EQ(s.records[k].reading.position_m[0], sample(k).reading.position_m[0]);
  }
  fs::remove(path);
}

// A tick with the syringe: its hand's reading, what the hand was sent and the syringe's state, each a
// value of its own.
TickSample syringe_sample(uint64_t k) {
  TickSample s = layered_sample(k);
  s.reading.plunger_input = uint32_t(PlungerInput::kHandlePosition);
  s.reading.plunger_force_n = 11.0 + 1e-3 * double(k);
  s.reading.plunger_position_m = std::nextafter(0.004, 1.0);
  s.command.plunger_force_n = 7.5;
  s.command.plunger_travel_m = 1e-4 * double(k);
  SyringeSnapshot& y = s.state.syringe;
  y.fluid = 2, y.layer = int32_t(k % 7) - 1;
  y.thumb_force_N = 9.0, y.pressure_Pa = 6.2e4 + double(k), y.travel_m = 1.0 / 7.0, y.flow_m3_per_s = 3e-6;
  y.injected_m3 = 1e-7 * double(k), y.work_J = 0.0125;
  return s;
}

// Payload 3 keeps the syringe hand and the syringe, bit for bit.
TEST(RecordingIntegrity, TheSyringeIsRecordedBitForBit) {
  static_assert(sizeof(SyringeSnapshot) == 2 * 4 + 6 * 8, "no padding: snapshots are compared bit for bit");
  const std::string path = temp_path("syringe.nrec");
  {
    SpscRing<TickSample> ring(4096);
    SessionRecorder recorder(path, kHeader, ring);
    for (uint64_t k = 0; k < 300; ++k) ring.push(syringe_sample(k));
    recorder.drain();
    recorder.stop(true);
    ASSERT_EQ(recorder.error(), "");
  }
  const Session s = read_session(path);
  ASSERT_EQ(s.records.size(), 300u);
  for (uint64_t k = 0; k < 300; ++k) {
    const TickSample expected = syringe_sample(k);
    EXPECT_EQ(std::memcmp(&s.records[k].state.syringe, &expected.state.syringe, sizeof(SyringeSnapshot)), 0)
        << "tick " << k;
    EXPECT_EQ(s.records[k].reading.plunger_input, expected.reading.plunger_input);
    EXPECT_EQ(s.records[k].reading.plunger_force_n, expected.reading.plunger_force_n);
    EXPECT_EQ(s.records[k].reading.plunger_position_m, expected.reading.plunger_position_m);
    EXPECT_EQ(s.records[k].command.plunger_force_n, expected.command.plunger_force_n);
    EXPECT_EQ(s.records[k].command.plunger_travel_m, expected.command.plunger_travel_m);
    EXPECT_TRUE(same_bits(s.records[k].state.tissue, expected.state.tissue));
  }
  fs::remove(path);
}

// A recording of payload 2 (the builds before the syringe) reads as it did: the syringe absent (its
// defaults), the syringe hand's reading none.
TEST(RecordingIntegrity, PayloadTwoRecordingsReadWithoutASyringe) {
  EXPECT_EQ(session_record_bytes(3), session_record_bytes(2) + 4 + 8 + 8 + 8 + 8 + 4 + 4 + 6 * 8);
  SessionHeader old = kHeader;
  old.payload_version = 2;
  std::vector<uint8_t> bytes = encode_header(old);
  const size_t block = bytes.size();
  bytes.resize(block + kBlockHeaderBytes);
  for (uint64_t k = 0; k < 40; ++k) encode_record(syringe_sample(k), bytes, 2);
  encode_block_header(bytes.data() + block, 0, 40, 2);
  const std::vector<uint8_t> end = encode_end(40, true);
  bytes.insert(bytes.end(), end.begin(), end.end());
  const std::string path = temp_path("payload2.nrec");
  write_bytes(path, bytes);
  const Session s = read_session(path);
  EXPECT_EQ(s.header.payload_version, 2u);
  ASSERT_EQ(s.records.size(), 40u);
  const SyringeSnapshot none;
  for (uint64_t k = 0; k < 40; ++k) {
    EXPECT_EQ(std::memcmp(&s.records[k].state.syringe, &none, sizeof none), 0) << "tick " << k;
    EXPECT_EQ(s.records[k].reading.plunger_input, 0u);
    EXPECT_TRUE(same_bits(s.records[k].state.tissue, layered_sample(k).state.tissue));
  }
  fs::remove(path);
}

// A version-3 recording of payload 1 (what the builds before the layered tissue's payload wrote) reads exactly as it
// did: the same record size, every field of payload 1 as written, the tissue at its defaults.
TEST(RecordingIntegrity, PayloadOneRecordingsStillReadExactlyAsBefore) {
  EXPECT_EQ(session_record_bytes(1), 684u);  // payload 1: the record_bytes of recordings without the layered tissue
  EXPECT_EQ(session_record_bytes(2), 684u + 4 * 4 + 8 + 24 + 8 + 24);
  SessionHeader old = kHeader;
  old.payload_version = 1;
  std::vector<uint8_t> bytes = encode_header(old);
  const size_t block = bytes.size();
  bytes.resize(block + kBlockHeaderBytes);
  for (uint64_t k = 0; k < 40; ++k) encode_record(layered_sample(k), bytes, 1);
  encode_block_header(bytes.data() + block, 0, 40, 1);
  const std::vector<uint8_t> end = encode_end(40, true);
  bytes.insert(bytes.end(), end.begin(), end.end());
  const std::string path = temp_path("payload1.nrec");
  write_bytes(path, bytes);

  const Session s = read_session(path);
  EXPECT_EQ(s.header.payload_version, 1u);
  EXPECT_TRUE(s.end.checksummed && s.end.closed && s.end.ran_to_end);
  ASSERT_EQ(s.records.size(), 40u);
  for (uint64_t k = 0; k < 40; ++k) {
    const TickSample expected = sample(k);
    EXPECT_EQ(s.records[k].tick, expected.tick);
    EXPECT_EQ(s.records[k].time_ns, expected.time_ns);
    EXPECT_EQ(s.records[k].reading.sequence, expected.reading.sequence);
    EXPECT_EQ(s.records[k].reading.position_m[0], expected.reading.position_m[0]);
    EXPECT_EQ(s.records[k].state.time_s, expected.state.time_s);
    EXPECT_TRUE(same_bits(s.records[k].state.tissue, TissueSnapshot{})) << "tick " << k;  // not in payload 1
  }
  // The payload-1 records re-encoded are the file's bytes: nothing was read from past a record.
  std::vector<uint8_t> again;
  for (const TickSample& r : s.records) encode_record(r, again, 1);
  EXPECT_TRUE(std::equal(again.begin(), again.end(), bytes.begin() + long(block + kBlockHeaderBytes)));
  fs::remove(path);
}

// A checksummed recording's bytes with `bytes` written at `at` inside block `block`'s records
// and the block's two checksums made valid again: damage no checksum sees.
void write_under_checksums(std::vector<uint8_t>& recording, int block, uint64_t at, const void* bytes, size_t size) {
  std::memcpy(&recording[at], bytes, size);
  const uint64_t head = block_offset(block);
  uint32_t count = 0;
  std::memcpy(&count, &recording[head + 12], 4);
  const uint32_t records_crc = crc32(&recording[head + kBlockHeaderBytes], count * session_record_bytes());
  std::memcpy(&recording[head + 16], &records_crc, 4);
  const uint32_t header_crc = crc32(&recording[head], 20);
  std::memcpy(&recording[head + 20], &header_crc, 4);
}

// Where the fields below start in a record (the order of visit_record in session_format.cpp):
// tick, time, period and compute time (4 x 8 bytes), the reading's sequence (8), its five 32-bit
// flags and counts (joint_count the second), its position (3 doubles), its joints (8 doubles).
constexpr uint64_t kReadingJointCount = 32 + 8 + 4;
constexpr uint64_t kReadingPosition = 32 + 8 + 5 * 4;
constexpr uint64_t kReadingJoints = kReadingPosition + 3 * 8;

TEST(RecordingIntegrity, ReadingsNoRunRecordsAreDamageNamingTheTickAndTheByteThoughTheChecksumsHold) {
  const std::string path = temp_path("content.nrec");
  const std::vector<uint8_t> good = recorded(path, 1000);
  const uint64_t record_300 =
      block_offset(1) + kBlockHeaderBytes + 44 * session_record_bytes();  // tick 300 is block 1's 45th
  const std::string where = path + ": tick 300 at byte " + std::to_string(record_300) + ": ";
  const std::string damaged = ": not what a run records (damaged)";
  struct Case {
    uint64_t at;
    double value;
    std::string problem;
  };
  const Case cases[] = {
      {kReadingJoints, std::nan(""), "reading joint_rad[0] = nan, outside [-1e+06, 1e+06]"},
      {kReadingJoints + 8, 1e300, "reading joint_rad[1] = 1e+300, outside [-1e+06, 1e+06]"},
      {kReadingPosition + 16, -1e300, "reading position_m[2] = -1e+300, outside [-10, 10]"},
      {kReadingPosition, 11.0, "reading position_m[0] = 11, outside [-10, 10]"},  // past the world (io::kWorldExtent_m)
  };
  for (const Case& c : cases) {
    std::vector<uint8_t> bad = good;
    write_under_checksums(bad, 1, record_300 + c.at, &c.value, 8);
    write_bytes(path, bad);
    EXPECT_EQ(error_of(path), where + c.problem + damaged);
    ReplayDevice replay(path);  // refused before its first tick
    EXPECT_THROW(replay.open(), RecordingError);
  }
  // A count past its array would be read past the array's end.
  std::vector<uint8_t> bad = good;
  const uint32_t count = 1u << 31;
  write_under_checksums(bad, 1, record_300 + kReadingJointCount, &count, 4);
  write_bytes(path, bad);
  EXPECT_EQ(error_of(path), where + "reading joint_count = 2147483648, more than 8" + damaged);
  fs::remove(path);
}

TEST(RecordingIntegrity, AStateThatIsNotFiniteIsRecordedOnlyWithTheFaultTheLoopLatchedOnIt) {
  const std::string path = temp_path("faulted.nrec");
  auto record_with = [&](uint32_t fault) {
    SpscRing<TickSample> ring(16);
    SessionRecorder recorder(path, kHeader, ring);
    TickSample s = sample(0);
    s.state.virtual_q[1] = std::nan("");
    s.reading.joint_rad[0] = std::numeric_limits<double>::infinity();
    s.state.fault = fault;
    ring.push(s);
    recorder.drain();
    recorder.stop(true);
  };
  record_with(1);  // the loop latched kNonFinite: the record holds what it met
  EXPECT_TRUE(std::isnan(read_session(path).records[0].state.virtual_q[1]));
  record_with(0);  // no fault: no run records it
  EXPECT_EQ(error_of(path),
            path + ": tick 0 at byte " + std::to_string(block_offset(0) + kBlockHeaderBytes) +
                ": reading joint_rad[0] = inf, outside [-1e+06, 1e+06]: not what a run records (damaged)");
  fs::remove(path);
}

TEST(RecordingIntegrity, TheFuzzersRecordingMutationReachesTheContentChecksNotTheChecksums) {
  const std::string path = temp_path("mutated.nrec");
  const std::vector<uint8_t> good = recorded(path, 600);
  int refused = 0;
  for (unsigned seed = 0; seed < 200; ++seed) {
    std::vector<uint8_t> bytes = good;
    std::mt19937 random(seed);
    ASSERT_EQ(fuzz::extreme_record_value(bytes.data(), bytes.size(), bytes.size(), random), bytes.size());
    write_bytes(path, bytes);
    const std::string error = error_of(path);
    EXPECT_EQ(error.find("checksum"), std::string::npos) << error;
    refused += error.find("not what a run records (damaged)") != std::string::npos;
  }
  // About half the places and values are refused: the readings' and commands' numbers, the counts
  // and a state's NaN or infinity are checked; the timing fields, the sequence, the buttons and a
  // state's finite numbers are not (a double written 4 bytes off its field may be neither).
  EXPECT_GT(refused, 40);
  fs::remove(path);
}

}  // namespace
}  // namespace needle::haptics
