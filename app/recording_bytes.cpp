#include "app/recording_bytes.hpp"

#include <algorithm>
#include <nlohmann/json.hpp>

#include "training/sessions/recording_identity.hpp"

namespace needle::app {

std::string encode_session(const haptics::Session& session) {
  constexpr size_t kBlockRecords = 256;  // as the recorder writes them
  const std::vector<uint8_t> header = haptics::encode_header(session.header);
  std::string out(header.begin(), header.end());
  std::vector<uint8_t> block;
  for (size_t first = 0; first < session.records.size(); first += kBlockRecords) {
    const size_t count = std::min(kBlockRecords, session.records.size() - first);
    block.assign(haptics::kBlockHeaderBytes, 0);
    for (size_t k = first; k < first + count; ++k)
      haptics::encode_record(session.records[k], block, session.header.payload_version);
    haptics::encode_block_header(block.data(), first, uint32_t(count), session.header.payload_version);
    out.append(block.begin(), block.end());
  }
  if (session.end.closed) {
    const std::vector<uint8_t> end = haptics::encode_end(session.records.size(), session.end.ran_to_end);
    out.append(end.begin(), end.end());
  }
  return out;
}

std::string context_for_session(const std::string& context, const std::string& uid) {
  nlohmann::json j = nlohmann::json::parse(context);
  j[training::kRecordingSessionKey] = uid;
  return j.dump();
}

}  // namespace needle::app
