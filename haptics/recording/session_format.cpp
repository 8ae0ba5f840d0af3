#include "haptics/recording/session_format.hpp"

#include <bit>
#include <cstring>
#include <fstream>
#include <iterator>

namespace needle::haptics {
namespace {

static_assert(std::endian::native == std::endian::little, "the recording format is little-endian");

constexpr char kMagic[8] = {'N', 'E', 'E', 'D', 'L', 'R', 'E', 'C'};

// One field list serves encoding, decoding and sizing: the visitor is called with every
// field of the record in file order.
template <typename Visitor>
void visit_record(Visitor& v, TickSample& s) {
  v(s.tick), v(s.time_ns), v(s.period_ns), v(s.compute_ns);
  DeviceReading& r = s.reading;
  v(r.sequence), v(r.connected), v(r.joint_count), v(r.buttons), v(r.has_sensed_force), v(r.has_joint_velocity);
  v(r.position_m), v(r.joint_rad), v(r.joint_velocity_rad_s), v(r.sensed_force_n), v(r.sensed_torque_nm);
  DeviceCommand& c = s.command;
  v(c.space), v(c.joint_count), v(c.force_n), v(c.torque_nm);
  ToolSnapshot& t = s.state;
  v(t.tick), v(t.time_s), v(t.needle_tip_m), v(t.needle_orientation), v(t.virtual_q), v(t.virtual_dq);
  v(t.joint_count), v(t.contact), v(t.active_constraint), v(t.multiplier_count), v(t.multipliers);
  v(t.operator_force_n), v(t.environment_force_n), v(t.device_force_n), v(t.fault), v(t.reserved);
}

struct Sizer {
  std::size_t bytes = 0;
  template <typename T>
  void operator()(const T&) { bytes += sizeof(T); }
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
bool take(const std::vector<uint8_t>& data, std::size_t& at, T& value) {
  if (data.size() - at < sizeof(T)) return false;
  std::memcpy(&value, data.data() + at, sizeof(T));
  at += sizeof(T);
  return true;
}

}  // namespace

std::size_t session_record_bytes() {
  static const std::size_t bytes = [] {
    Sizer sizer;
    TickSample s;
    visit_record(sizer, s);
    return sizer.bytes;
  }();
  return bytes;
}

std::vector<uint8_t> encode_header(const SessionHeader& header) {
  std::vector<uint8_t> out(kMagic, kMagic + sizeof kMagic);
  put(out, header.version);
  put(out, static_cast<uint32_t>(session_record_bytes()));
  put(out, header.rate_hz);
  put(out, header.unix_time_s);
  put(out, static_cast<uint32_t>(header.device.size()));
  out.insert(out.end(), header.device.begin(), header.device.end());
  put(out, static_cast<uint32_t>(header.context.size()));
  out.insert(out.end(), header.context.begin(), header.context.end());
  return out;
}

void encode_record(const TickSample& sample, std::vector<uint8_t>& out) {
  Writer writer{out};
  visit_record(writer, const_cast<TickSample&>(sample));
}

Session read_session(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw RecordingError(path + ": cannot be opened");
  const std::vector<uint8_t> data((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  auto fail = [&path](const std::string& element, const std::string& what) {
    return RecordingError(path + ": " + element + ": " + what);
  };
  if (data.size() < sizeof kMagic || std::memcmp(data.data(), kMagic, sizeof kMagic) != 0)
    throw fail("header", "not a needle-sim session recording (expected magic NEEDLREC)");
  std::size_t at = sizeof kMagic;
  Session session;
  uint32_t record_bytes = 0, name_length = 0;
  if (!take(data, at, session.header.version)) throw fail("header", "truncated before the version");
  if (session.header.version < 1 || session.header.version > kSessionFormatVersion)
    throw fail("header", "format version " + std::to_string(session.header.version) + ", this build reads versions 1 to " +
                             std::to_string(kSessionFormatVersion));
  if (!take(data, at, record_bytes) || !take(data, at, session.header.rate_hz) ||
      !take(data, at, session.header.unix_time_s) || !take(data, at, name_length) || data.size() - at < name_length)
    throw fail("header", "truncated");
  if (record_bytes != session_record_bytes())
    throw fail("header", "record size " + std::to_string(record_bytes) + " bytes, expected " +
                             std::to_string(session_record_bytes()));
  session.header.device.assign(reinterpret_cast<const char*>(data.data() + at), name_length);
  at += name_length;
  if (session.header.version >= 2) {
    uint32_t context_length = 0;
    if (!take(data, at, context_length) || data.size() - at < context_length) throw fail("header", "truncated context");
    session.header.context.assign(reinterpret_cast<const char*>(data.data() + at), context_length);
    at += context_length;
  }

  const std::size_t body = data.size() - at;
  // A kill can cut the last record short: everything before it is still good, so the
  // partial record is dropped rather than failing the whole file.
  session.records.resize(body / record_bytes);
  session.trailing_bytes = body % record_bytes;
  for (TickSample& s : session.records) {
    Reader reader{data.data() + at};
    visit_record(reader, s);
    at += record_bytes;
  }
  return session;
}

}  // namespace needle::haptics
