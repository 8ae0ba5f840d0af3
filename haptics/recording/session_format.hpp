// The session recording file: a versioned header, then one fixed-size record per tick
// holding the device stream (reading and the command actually sent) and the simulation
// state. Little-endian, doubles stored bit for bit, so a replay can be compared exactly.
//
//   header: "NEEDLREC" | u32 version | u32 record_bytes | f64 rate_hz | i64 unix_time_s |
//           u32 name_length | device name bytes | u32 context_length | context bytes
//   (version 1 has no context; it is still read, with an empty context)
//   record: see visit_record() in session_format.cpp (field order is the format)
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "haptics/realtime/tick_sample.hpp"

namespace needle::haptics {

inline constexpr uint32_t kSessionFormatVersion = 2;

struct SessionHeader {
  uint32_t version = kSessionFormatVersion;
  double rate_hz = 0.0;
  int64_t unix_time_s = 0;
  std::string device;   // the device spec the session ran with
  std::string context;  // what the application needs to rebuild the session (opaque here)
};

// A recording that cannot be read: what() reads "FILE: ELEMENT: what is wrong".
struct RecordingError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Size of one encoded record in bytes.
std::size_t session_record_bytes();

std::vector<uint8_t> encode_header(const SessionHeader& header);
// Appends one record to `out` (reserved by the caller; no allocation when capacity allows).
void encode_record(const TickSample& sample, std::vector<uint8_t>& out);

struct Session {
  SessionHeader header;
  std::vector<TickSample> records;
  std::size_t trailing_bytes = 0;  // a last record cut short (the process was killed mid-write)
};

// Reads a whole file; throws RecordingError naming the file and the bad element.
Session read_session(const std::string& path);

}  // namespace needle::haptics
