// The session recording file (docs/SESSIONS.md, "Recordings"): a header checked by its own
// checksum, then the ticks in blocks, each with its record count and a checksum, then an end mark
// written when the recorder closes. Little-endian, doubles stored bit for bit, so a replay can be
// compared exactly. Damage is an error naming the file and the byte offset; a file cut short (the
// run was killed) reads up to its last whole block, and says so.
//
//   header (version 3):
//     "NEEDLREC" | u32 version | u32 header_bytes | u32 payload_version | u32 record_bytes |
//     f64 rate_hz | i64 unix_time_s | u32 device_length | device | u32 context_length | context |
//     u32 CRC-32 of every header byte before it
//   block:  "NBLK" | u64 first_record | u32 record_count | u32 CRC-32 of the records |
//           u32 CRC-32 of the 20 bytes before it; then record_count records of record_bytes each
//   end:    "NEND" | u64 record_total | u32 flags (1: the session ran to its end) |
//           u32 CRC-32 of the 16 bytes before it
//   record: the fields of visit_record() in session_format.cpp for the header's payload_version.
//           The framing never assumes a record's size: it is the header's record_bytes.
//
//   Versions 1 and 2 (read, no longer written): "NEEDLREC" | u32 version | u32 record_bytes |
//   f64 rate_hz | i64 unix_time_s | u32 device_length | device | (2: u32 context_length | context),
//   then bare records of payload version 1: no checksums, no end mark.
#pragma once

#include <cstdint>
#include <cstdio>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "haptics/realtime/tick_sample.hpp"

namespace needle::haptics {

inline constexpr uint32_t kSessionFormatVersion = 3;
// The layout of one record. A new field of TickSample is appended to visit_record() behind
// `if (version >= N)` with N the next payload version: recordings of older payloads then still
// read, the new field at its default.
// Payload 1: the tick, device reading and command, tool state. Payload 2 adds the
// layered tissue at the needle (ToolSnapshot::tissue). Payload 3 adds the syringe: the syringe hand's
// reading (DeviceReading::plunger_*), what it was sent (DeviceCommand::plunger_*) and the syringe's
// state (ToolSnapshot::syringe).
inline constexpr uint32_t kPayloadVersion = 3;
// The recorder writes at most this many records in a block; a reader refuses more.
inline constexpr uint32_t kMaxBlockRecords = 4096;

struct SessionHeader {
  uint32_t version = kSessionFormatVersion;
  double rate_hz = 0.0;
  int64_t unix_time_s = 0;
  std::string device;   // the device spec the session ran with
  std::string context;  // what the application needs to rebuild the session (opaque here)
  uint32_t payload_version = kPayloadVersion;
};

// A recording that cannot be read: what() reads "FILE: ELEMENT: what is wrong", the element
// being the header, or a block or the end at its byte offset.
struct RecordingError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Size of one encoded record of `payload_version` in bytes.
std::size_t session_record_bytes(uint32_t payload_version = kPayloadVersion);

// The header, with its checksum (version 3 only: older versions are not written). The recorder
// writes kPayloadVersion; an older payload_version is for tests of what older builds wrote.
std::vector<uint8_t> encode_header(const SessionHeader& header);
// Appends one record to `out` (reserved by the caller; no allocation when capacity allows).
void encode_record(const TickSample& sample, std::vector<uint8_t>& out, uint32_t payload_version = kPayloadVersion);

inline constexpr std::size_t kBlockHeaderBytes = 24;
inline constexpr std::size_t kEndBytes = 20;
// Fills the kBlockHeaderBytes at `at` for the `count` records that follow them.
void encode_block_header(uint8_t* at, uint64_t first_record, uint32_t count,
                         uint32_t payload_version = kPayloadVersion);
std::vector<uint8_t> encode_end(uint64_t record_total, bool ran_to_end);

// What a reader found besides the records.
struct RecordingEnd {
  bool checksummed = false;        // version 3: the header and every block were checked
  bool closed = false;             // the end mark is there: the recorder closed the file
  bool ran_to_end = false;         // ...and its session ran to its end (not a window closed early)
  uint64_t whole_bytes = 0;        // the header and the whole blocks: where a cut file stops being whole
  std::size_t trailing_bytes = 0;  // after them, a block cut short (or, before version 3, a record)
};

// Reads a recording a block at a time: the header is checked before anything else is read (a
// folder, a device, another kind of file or a header whose checksum fails are refused at once),
// then each block is checked before its records are handed out. Nothing reads the whole file.
class RecordingReader {
 public:
  // Throws RecordingError naming the file.
  explicit RecordingReader(std::string path);
  RecordingReader(const RecordingReader&) = delete;
  RecordingReader& operator=(const RecordingReader&) = delete;

  const SessionHeader& header() const { return header_; }
  // Replaces `records` with the next block's; false at the end of the file. Throws
  // RecordingError naming the file and the byte offset of a damaged block, or the tick and the
  // byte of a record whose checksum holds but whose content no run records (a NaN or 1e300
  // reading, a count past its array: docs/SESSIONS.md, "Reading").
  bool next(std::vector<TickSample>& records);
  // Valid once next() has returned false.
  const RecordingEnd& end() const { return end_; }
  uint64_t records_read() const { return records_read_; }

 private:
  [[noreturn]] void fail(const std::string& element, const std::string& what) const;
  bool next_block(std::vector<TickSample>& records);
  bool next_bare(std::vector<TickSample>& records);  // versions 1 and 2
  // The `count` records in buffer_ into `records`, the first at byte `at` of the file; throws
  // RecordingError naming the tick and its byte when one holds what no run records.
  void decode_records(std::vector<TickSample>& records, std::size_t count, uint64_t at);

  std::string path_;
  // Owned from the moment it opens: a header refused by the constructor must not leak the file.
  std::unique_ptr<std::FILE, int (*)(std::FILE*)> file_{nullptr, &std::fclose};
  uint64_t size_ = 0;    // bytes in the file
  uint64_t offset_ = 0;  // bytes consumed
  std::size_t record_bytes_ = 0;
  uint64_t max_records_ = 0;
  uint64_t records_read_ = 0;
  bool done_ = false;
  SessionHeader header_;
  RecordingEnd end_;
  std::vector<uint8_t> buffer_;
};

struct Session {
  SessionHeader header;
  std::vector<TickSample> records;
  RecordingEnd end;
};

// The header alone; throws RecordingError naming the file.
SessionHeader read_header(const std::string& path);
// Every record, through RecordingReader; throws RecordingError naming the file and the element.
Session read_session(const std::string& path);

// What a reader of this recording should be told, one line each, empty when nothing: a file cut
// short ("FILE: cut at byte B after N ticks ..."), a format without checksums.
std::vector<std::string> recording_notes(const std::string& path, const RecordingEnd& end, uint64_t records);

}  // namespace needle::haptics
