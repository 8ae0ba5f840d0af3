#include "haptics/recording/session_format.hpp"

#include <sys/stat.h>

#include <bit>
#include <cerrno>
#include <cmath>
#include <cstring>

#include "haptics/recording/crc32.hpp"
#include "io/input_limits.hpp"

namespace needle::haptics {
namespace {

static_assert(std::endian::native == std::endian::little, "the recording format is little-endian");

constexpr char kMagic[8] = {'N', 'E', 'E', 'D', 'L', 'R', 'E', 'C'};
constexpr char kBlockMagic[4] = {'N', 'B', 'L', 'K'};
constexpr char kEndMagic[4] = {'N', 'E', 'N', 'D'};
// Bounds a header is checked against before anything it announces is read or allocated.
constexpr uint32_t kMaxDeviceBytes = 4096;
constexpr uint32_t kMaxContextBytes = 16u << 20;
// Version 3's fixed part: magic, version, header_bytes, payload_version, record_bytes, rate, time.
constexpr std::size_t kFixedHeaderBytes = 8 + 4 + 4 + 4 + 4 + 8 + 8;

// One field list serves encoding, decoding and sizing: the visitor is called with every field of
// a record of payload version `version` in file order. Fields added later go at the end, behind
// `if (version >= N)`.
template <typename Visitor>
void visit_record(Visitor& v, TickSample& s, uint32_t version) {
  v(s.tick), v(s.time_ns), v(s.period_ns), v(s.compute_ns);
  DeviceReading& r = s.reading;
  v(r.sequence), v(r.connected), v(r.joint_count), v(r.buttons), v(r.has_sensed_force), v(r.has_joint_velocity);
  v(r.position_m), v(r.joint_rad), v(r.joint_velocity_rad_s), v(r.sensed_force_n), v(r.sensed_torque_nm);
  DeviceCommand& c = s.command;
  v(c.space), v(c.joint_count), v(c.force_n), v(c.torque_nm);
  ToolSnapshot& t = s.state;
  v(t.tick), v(t.time_s), v(t.needle_tip_m), v(t.needle_orientation), v(t.virtual_q), v(t.virtual_dq);
  v(t.joint_count), v(t.contact), v(t.active_constraint), v(t.multiplier_count), v(t.multipliers);
  v(t.operator_force_n), v(t.environment_force_n), v(t.device_force_n), v(t.fault), v(t.limits);
  if (version >= 2) {  // the layered tissue at the needle
    TissueSnapshot& l = t.tissue;
    v(l.tip_layer), v(l.punctured_layers), v(l.surface_layer), v(l.bone_layer), v(l.axial_force_N), v(l.bone_force_n);
    v(l.deflection_m), v(l.surface_point_m);
  }
  if (version >= 3) {  // the syringe hand's input, what it was sent, and the syringe
    v(r.plunger_input), v(r.plunger_force_n), v(r.plunger_position_m);
    v(c.plunger_force_n), v(c.plunger_travel_m);
    SyringeSnapshot& y = t.syringe;
    v(y.fluid), v(y.layer), v(y.thumb_force_N), v(y.pressure_Pa), v(y.travel_m), v(y.flow_m3_per_s), v(y.injected_m3),
        v(y.work_J);
  }
}

struct Sizer {
  std::size_t bytes = 0;
  template <typename T>
  void operator()(const T&) {
    bytes += sizeof(T);
  }
};

struct Writer {
  std::vector<uint8_t>& out;
  template <typename T>
  void operator()(const T& value) {
    const auto* p = reinterpret_cast<const uint8_t*>(&value);
    out.insert(out.end(), p, p + sizeof(T));
  }
};

struct Reader {
  const uint8_t* at;
  template <typename T>
  void operator()(T& value) {
    std::memcpy(&value, at, sizeof(T));
    at += sizeof(T);
  }
};

template <typename T>
void put(std::vector<uint8_t>& out, const T& value) {
  Writer{out}(value);
}

template <typename T>
T get(const uint8_t* at) {
  T value;
  std::memcpy(&value, at, sizeof(T));
  return value;
}

template <typename T>
void put_at(uint8_t* at, const T& value) {
  std::memcpy(at, &value, sizeof(T));
}

std::string at_byte(uint64_t offset) { return "at byte " + std::to_string(offset); }

std::string hz(double rate) {
  char text[32];
  std::snprintf(text, sizeof text, "%g Hz", rate);
  return text;
}

// The largest magnitude of a recorded reading or command other than a position, in SI units
// (rad, rad/s, N, N·m): no desk device reads or is sent a million of any of them, so such a
// number is damage (1e300 written over a joint), not a reading. Positions stay within the world
// (io::kWorldExtent_m).
constexpr double kMaxReading = 1e6;

// "reading joint_rad[2] = nan, outside [-1e+06, 1e+06]" for the first of `values` outside
// [-bound, bound] (NaN included), "" when none is.
std::string out_of_bound(const char* name, const double* values, int count, double bound) {
  for (int i = 0; i < count; ++i)
    if (!(std::abs(values[i]) <= bound)) {
      char text[160];
      std::snprintf(text, sizeof text, "%s[%d] = %g, outside [%g, %g]", name, i, values[i], -bound, bound);
      return text;
    }
  return {};
}

// "state virtual_q[1] = nan, not finite" for the first of `values` that is not, "" when all are.
std::string not_finite(const char* name, const double* values, int count) {
  for (int i = 0; i < count; ++i)
    if (!std::isfinite(values[i])) {
      char index[16] = "";
      if (count > 1) std::snprintf(index, sizeof index, "[%d]", i);
      char text[160];
      std::snprintf(text, sizeof text, "%s%s = %g, not finite", name, index, values[i]);
      return text;
    }
  return {};
}

// "state syringe pressure_Pa = nan, not finite" for the first of the syringe's numbers that is not.
std::string syringe_state_problem(const SyringeSnapshot& y) {
  const std::pair<const char*, double> numbers[] = {
      {"state syringe thumb_force_N", y.thumb_force_N}, {"state syringe pressure_Pa", y.pressure_Pa},
      {"state syringe travel_m", y.travel_m},           {"state syringe flow_m3_per_s", y.flow_m3_per_s},
      {"state syringe injected_m3", y.injected_m3},     {"state syringe work_J", y.work_J}};
  for (const auto& [name, value] : numbers)
    if (std::string problem = not_finite(name, &value, 1); !problem.empty()) return problem;
  return {};
}

// What makes a decoded record one no run can have written, or "" (docs/SESSIONS.md, "Reading"):
// counts past the arrays they count, an unknown contact or command space, a layer index outside
// the punctured set's 32 bits; and, unless the loop had latched a fault on it (then it holds what
// the loop met, NaN included, as the loop recorded it), a reading or a command that is not finite
// or past kMaxReading (a position past the world), a state that is not finite (a tip past the world).
std::string record_problem(const TickSample& s) {
  const DeviceReading& r = s.reading;
  const DeviceCommand& c = s.command;
  const ToolSnapshot& t = s.state;
  auto count = [](const char* name, uint32_t n, int most) {
    return n > uint32_t(most) ? std::string(name) + " = " + std::to_string(n) + ", more than " + std::to_string(most)
                              : std::string();
  };
  for (const std::string& problem :
       {count("reading joint_count", r.joint_count, kMaxDeviceJoints),
        count("command joint_count", c.joint_count, kMaxDeviceJoints),
        count("command space", uint32_t(c.space), int(CommandSpace::kJointTorque)),
        count("state joint_count", t.joint_count, kMaxSnapshotJoints),
        count("state multiplier_count", t.multiplier_count, kMaxMultipliers),
        count("state contact", uint32_t(t.contact), int(ContactState::kTissue)),
        count("reading plunger_input", r.plunger_input, int(PlungerInput::kHandlePosition)),
        count("state syringe fluid", t.syringe.fluid, 2)})
    if (!problem.empty()) return problem;
  for (const int32_t layer : {t.tissue.tip_layer, t.tissue.surface_layer, t.tissue.bone_layer, t.syringe.layer})
    if (layer < -1 || layer > 31) return "state layer index " + std::to_string(layer) + ", outside [-1, 31]";
  if (t.fault != 0) return {};
  const TissueSnapshot& l = t.tissue;
  for (const std::string& problem :
       {out_of_bound("reading position_m", r.position_m, 3, io::kWorldExtent_m),
        out_of_bound("reading joint_rad", r.joint_rad, kMaxDeviceJoints, kMaxReading),
        out_of_bound("reading joint_velocity_rad_s", r.joint_velocity_rad_s, kMaxDeviceJoints, kMaxReading),
        out_of_bound("reading sensed_force_n", r.sensed_force_n, 3, kMaxReading),
        out_of_bound("reading sensed_torque_nm", r.sensed_torque_nm, 3, kMaxReading),
        out_of_bound("command force_n", c.force_n, 3, kMaxReading),
        out_of_bound("command torque_nm", c.torque_nm, kMaxDeviceJoints, kMaxReading),
        not_finite("state time_s", &t.time_s, 1),
        not_finite("state axial_force_N", &l.axial_force_N, 1),
        not_finite("state deflection_m", &l.deflection_m, 1),
        out_of_bound("state needle_tip_m", t.needle_tip_m, 3, io::kWorldExtent_m),
        not_finite("state needle_orientation", t.needle_orientation, 4),
        not_finite("state virtual_q", t.virtual_q, kMaxSnapshotJoints),
        not_finite("state virtual_dq", t.virtual_dq, kMaxSnapshotJoints),
        not_finite("state multipliers", t.multipliers, kMaxMultipliers),
        not_finite("state operator_force_n", t.operator_force_n, 3),
        not_finite("state environment_force_n", t.environment_force_n, 3),
        not_finite("state device_force_n", t.device_force_n, 3),
        not_finite("state bone_force_n", l.bone_force_n, 3),
        out_of_bound("state surface_point_m", l.surface_point_m, 3, io::kWorldExtent_m),
        out_of_bound("reading plunger_force_n", &r.plunger_force_n, 1, kMaxReading),
        out_of_bound("reading plunger_position_m", &r.plunger_position_m, 1, io::kWorldExtent_m),
        out_of_bound("command plunger_force_n", &c.plunger_force_n, 1, kMaxReading),
        out_of_bound("command plunger_travel_m", &c.plunger_travel_m, 1, io::kWorldExtent_m),
        syringe_state_problem(t.syringe)})
    if (!problem.empty()) return problem;
  return {};
}

}  // namespace

std::size_t session_record_bytes(uint32_t payload_version) {
  Sizer sizer;
  TickSample s;
  visit_record(sizer, s, payload_version);
  return sizer.bytes;
}

std::vector<uint8_t> encode_header(const SessionHeader& header) {
  std::vector<uint8_t> out(kMagic, kMagic + sizeof kMagic);
  put(out, kSessionFormatVersion);
  put(out, uint32_t{0});  // header_bytes, filled in below
  put(out, header.payload_version);
  put(out, static_cast<uint32_t>(session_record_bytes(header.payload_version)));
  put(out, header.rate_hz);
  put(out, header.unix_time_s);
  put(out, static_cast<uint32_t>(header.device.size()));
  out.insert(out.end(), header.device.begin(), header.device.end());
  put(out, static_cast<uint32_t>(header.context.size()));
  out.insert(out.end(), header.context.begin(), header.context.end());
  put_at(out.data() + 12, static_cast<uint32_t>(out.size() + 4));
  put(out, crc32(out.data(), out.size()));
  return out;
}

void encode_record(const TickSample& sample, std::vector<uint8_t>& out, uint32_t payload_version) {
  Writer writer{out};
  visit_record(writer, const_cast<TickSample&>(sample), payload_version);
}

void encode_block_header(uint8_t* at, uint64_t first_record, uint32_t count, uint32_t payload_version) {
  const std::size_t records = std::size_t(count) * session_record_bytes(payload_version);
  std::memcpy(at, kBlockMagic, 4);
  put_at(at + 4, first_record);
  put_at(at + 12, count);
  put_at(at + 16, crc32(at + kBlockHeaderBytes, records));
  put_at(at + 20, crc32(at, 20));
}

std::vector<uint8_t> encode_end(uint64_t record_total, bool ran_to_end) {
  std::vector<uint8_t> out(kEndMagic, kEndMagic + 4);
  put(out, record_total);
  put(out, uint32_t{ran_to_end ? 1u : 0u});
  put(out, crc32(out.data(), out.size()));
  return out;
}

RecordingReader::RecordingReader(std::string path) : path_(std::move(path)) {
  struct stat st {};
  if (::stat(path_.c_str(), &st) != 0) fail("", std::string("cannot be opened: ") + std::strerror(errno));
  if (S_ISDIR(st.st_mode)) fail("", "is a folder, not a recording");
  if (!S_ISREG(st.st_mode)) fail("", "not a regular file (a device or a pipe), not a recording");
  file_.reset(std::fopen(path_.c_str(), "rb"));
  if (file_ == nullptr) fail("", std::string("cannot be opened: ") + std::strerror(errno));
  size_ = uint64_t(st.st_size);

  auto read_exactly = [this](std::size_t bytes) {
    buffer_.resize(bytes);
    return std::fread(buffer_.data(), 1, bytes, file_.get()) == bytes;
  };
  // Magic and version first: 12 bytes decide whether anything more is read.
  if (!read_exactly(12) || std::memcmp(buffer_.data(), kMagic, sizeof kMagic) != 0)
    fail("header", "not a needle-sim session recording (expected magic NEEDLREC)");
  header_.version = get<uint32_t>(buffer_.data() + 8);
  if (header_.version < 1 || header_.version > kSessionFormatVersion)
    fail("header", "format version " + std::to_string(header_.version) + ", this build reads versions 1 to " +
                       std::to_string(kSessionFormatVersion));

  std::size_t fixed = 0, header_bytes = 0;
  if (header_.version >= 3) {
    if (!read_exactly(4)) fail("header", "truncated");
    header_bytes = get<uint32_t>(buffer_.data());
    constexpr std::size_t kMaxHeaderBytes = kFixedHeaderBytes + 4 + kMaxDeviceBytes + 4 + kMaxContextBytes + 4;
    if (header_bytes < kFixedHeaderBytes + 12 || header_bytes > kMaxHeaderBytes)
      fail("header", "length " + std::to_string(header_bytes) + " bytes is not a header's");
    if (header_bytes > size_) fail("header", "truncated (the file has " + std::to_string(size_) + " bytes)");
    // The whole header is checked before any of its fields is believed.
    std::vector<uint8_t> head(header_bytes);
    std::fseek(file_.get(), 0, SEEK_SET);
    if (std::fread(head.data(), 1, header_bytes, file_.get()) != header_bytes) fail("header", "truncated");
    if (crc32(head.data(), header_bytes - 4) != get<uint32_t>(head.data() + header_bytes - 4))
      fail("header", "checksum mismatch: the header was changed or damaged");
    buffer_ = std::move(head);
    header_.payload_version = get<uint32_t>(buffer_.data() + 16);
    record_bytes_ = get<uint32_t>(buffer_.data() + 20);
    fixed = 24;
  } else {
    std::vector<uint8_t> head = buffer_;                 // the magic and the version, as read
    if (!read_exactly(20)) fail("header", "truncated");  // record_bytes, rate, time
    head.insert(head.end(), buffer_.begin(), buffer_.end());
    buffer_ = std::move(head);
    header_.payload_version = 1;
    record_bytes_ = get<uint32_t>(buffer_.data() + 12);
    fixed = 16;
  }
  if (header_.payload_version < 1 || header_.payload_version > kPayloadVersion)
    fail("header", "payload version " + std::to_string(header_.payload_version) + ", this build reads versions 1 to " +
                       std::to_string(kPayloadVersion));
  if (record_bytes_ != session_record_bytes(header_.payload_version))
    fail("header", "record size " + std::to_string(record_bytes_) + " bytes, expected " +
                       std::to_string(session_record_bytes(header_.payload_version)) + " for payload version " +
                       std::to_string(header_.payload_version));
  header_.rate_hz = get<double>(buffer_.data() + fixed);
  header_.unix_time_s = get<int64_t>(buffer_.data() + fixed + 8);
  if (!(header_.rate_hz >= 1.0 && header_.rate_hz <= 1e5))
    fail("header", "loop rate " + hz(header_.rate_hz) + " is not one a session runs at");

  // The two strings, their lengths bounded before anything is allocated for them.
  std::size_t at = fixed + 16;
  auto string_field = [&](std::string& out, uint32_t max, const char* what) {
    if (header_.version < 3) {
      if (!read_exactly(4)) fail("header", std::string("truncated before the ") + what);
    } else if (at + 4 > header_bytes - 4) {
      fail("header", std::string("truncated before the ") + what);
    }
    const uint8_t* p = header_.version < 3 ? buffer_.data() : buffer_.data() + at;
    const uint32_t length = get<uint32_t>(p);
    at += 4;
    if (length > max)
      fail("header",
           std::string(what) + " of " + std::to_string(length) + " bytes (at most " + std::to_string(max) + ")");
    if (header_.version < 3) {
      std::vector<uint8_t> bytes(length);
      if (length > size_ || std::fread(bytes.data(), 1, length, file_.get()) != length)
        fail("header", std::string("truncated ") + what);
      out.assign(bytes.begin(), bytes.end());
    } else {
      if (at + length > header_bytes - 4) fail("header", std::string("truncated ") + what);
      out.assign(reinterpret_cast<const char*>(buffer_.data() + at), length);
    }
    at += length;
  };
  string_field(header_.device, kMaxDeviceBytes, "device name");
  if (header_.version >= 2) string_field(header_.context, kMaxContextBytes, "context");
  if (header_.version >= 3 && at != header_bytes - 4) fail("header", "length does not match its fields");
  offset_ = header_.version >= 3 ? header_bytes : uint64_t(std::ftell(file_.get()));
  end_.checksummed = header_.version >= 3;
  end_.whole_bytes = offset_;

  // Sizes before records: a file longer than the longest session at this rate is refused now,
  // not after reading it.
  max_records_ = uint64_t(io::kMaxSessionSeconds * header_.rate_hz) + 1;
  const uint64_t most_bytes = max_records_ * (record_bytes_ + kBlockHeaderBytes) + kEndBytes;
  if (size_ - offset_ > most_bytes)
    fail("", std::to_string(size_) + " bytes: more than a session of at most " +
                 std::to_string(int(io::kMaxSessionSeconds / 60)) + " minutes at " + hz(header_.rate_hz) + " can hold");
}

void RecordingReader::fail(const std::string& element, const std::string& what) const {
  throw RecordingError(path_ + ": " + (element.empty() ? "" : element + ": ") + what);
}

bool RecordingReader::next(std::vector<TickSample>& records) {
  records.clear();
  if (done_) return false;
  const bool more = header_.version >= 3 ? next_block(records) : next_bare(records);
  if (!more) done_ = true;
  records_read_ += records.size();
  if (records_read_ > max_records_)
    fail("", "more than " + std::to_string(max_records_) + " ticks: longer than a session of at most " +
                 std::to_string(int(io::kMaxSessionSeconds / 60)) + " minutes");
  return more;
}

bool RecordingReader::next_bare(std::vector<TickSample>& records) {
  const uint64_t left = size_ - offset_;
  const std::size_t count = std::size_t(std::min<uint64_t>(left / record_bytes_, 256));
  if (count == 0) {
    end_.trailing_bytes = std::size_t(left);
    return false;
  }
  buffer_.resize(count * record_bytes_);
  if (std::fread(buffer_.data(), 1, buffer_.size(), file_.get()) != buffer_.size())
    fail(at_byte(offset_), "cannot be read");
  decode_records(records, count, offset_);
  offset_ += buffer_.size();
  end_.whole_bytes = offset_;
  return true;
}

bool RecordingReader::next_block(std::vector<TickSample>& records) {
  const uint64_t left = size_ - offset_;
  const std::string where = "block " + at_byte(offset_);
  // A file that ends here, or inside a block's header or records, was cut: what came before is whole.
  auto cut = [&] {
    end_.trailing_bytes = std::size_t(left);
    return false;
  };
  if (left < 4) return cut();
  buffer_.resize(4);
  if (std::fread(buffer_.data(), 1, 4, file_.get()) != 4) fail(where, "cannot be read");
  if (std::memcmp(buffer_.data(), kEndMagic, 4) == 0) {
    const std::string end_where = "end " + at_byte(offset_);
    if (left < kEndBytes) return cut();
    buffer_.resize(kEndBytes);
    if (std::fread(buffer_.data() + 4, 1, kEndBytes - 4, file_.get()) != kEndBytes - 4)
      fail(end_where, "cannot be read");
    if (crc32(buffer_.data(), 16) != get<uint32_t>(buffer_.data() + 16)) fail(end_where, "checksum mismatch (damaged)");
    const uint64_t total = get<uint64_t>(buffer_.data() + 4);
    if (total != records_read_)
      fail(end_where, "says " + std::to_string(total) + " ticks, the blocks hold " + std::to_string(records_read_));
    if (left > kEndBytes) fail(end_where, std::to_string(left - kEndBytes) + " bytes after the end of the recording");
    end_.closed = true;
    end_.ran_to_end = (get<uint32_t>(buffer_.data() + 12) & 1u) != 0;
    offset_ += kEndBytes;
    end_.whole_bytes = offset_;
    return false;
  }
  if (std::memcmp(buffer_.data(), kBlockMagic, 4) != 0) fail(where, "not a block of records (damaged)");
  if (left < kBlockHeaderBytes) return cut();
  buffer_.resize(kBlockHeaderBytes);
  if (std::fread(buffer_.data() + 4, 1, kBlockHeaderBytes - 4, file_.get()) != kBlockHeaderBytes - 4)
    fail(where, "cannot be read");
  if (crc32(buffer_.data(), 20) != get<uint32_t>(buffer_.data() + 20))
    fail(where, "header checksum mismatch (damaged)");
  const uint64_t first = get<uint64_t>(buffer_.data() + 4);
  const uint32_t count = get<uint32_t>(buffer_.data() + 12);
  const uint32_t records_crc = get<uint32_t>(buffer_.data() + 16);
  if (first != records_read_)
    fail(where, "starts at tick " + std::to_string(first) + ", expected " + std::to_string(records_read_) +
                    " (a block is missing or repeated)");
  if (count == 0 || count > kMaxBlockRecords)
    fail(where, std::to_string(count) + " records (expected 1 to " + std::to_string(kMaxBlockRecords) + ")");
  const std::size_t bytes = std::size_t(count) * record_bytes_;
  if (left - kBlockHeaderBytes < bytes) return cut();
  buffer_.resize(bytes);
  if (std::fread(buffer_.data(), 1, bytes, file_.get()) != bytes) fail(where, "cannot be read");
  if (crc32(buffer_.data(), bytes) != records_crc) fail(where, "records checksum mismatch (damaged)");
  decode_records(records, count, offset_ + kBlockHeaderBytes);
  offset_ += kBlockHeaderBytes + bytes;
  end_.whole_bytes = offset_;
  return true;
}

void RecordingReader::decode_records(std::vector<TickSample>& records, std::size_t count, uint64_t at) {
  records.resize(count);
  for (std::size_t k = 0; k < count; ++k) {
    Reader reader{buffer_.data() + k * record_bytes_};
    visit_record(reader, records[k], header_.payload_version);
    if (const std::string problem = record_problem(records[k]); !problem.empty())
      fail("tick " + std::to_string(records_read_ + k) + " " + at_byte(at + k * record_bytes_),
           problem + ": not what a run records (damaged)");
  }
}

SessionHeader read_header(const std::string& path) { return RecordingReader(path).header(); }

Session read_session(const std::string& path) {
  RecordingReader reader(path);
  Session session;
  session.header = reader.header();
  std::vector<TickSample> block;
  while (reader.next(block)) session.records.insert(session.records.end(), block.begin(), block.end());
  session.end = reader.end();
  return session;
}

std::vector<std::string> recording_notes(const std::string& path, const RecordingEnd& end, uint64_t records) {
  std::vector<std::string> notes;
  if (!end.checksummed)
    notes.push_back(path + ": an older format without checksums: damage to its records cannot be detected");
  if (end.checksummed && !end.closed)
    notes.push_back(
        path + ": cut at byte " + std::to_string(end.whole_bytes) + " after " + std::to_string(records) +
        " ticks (its run stopped without closing it" +
        (end.trailing_bytes ? ", " + std::to_string(end.trailing_bytes) + " bytes of a last block lost" : "") +
        "): read up to there");
  if (!end.checksummed && end.trailing_bytes)
    notes.push_back(path + ": " + std::to_string(end.trailing_bytes) + " bytes of a last record cut short, dropped");
  return notes;
}

}  // namespace needle::haptics
