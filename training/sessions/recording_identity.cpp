#include "training/sessions/recording_identity.hpp"

#include <nlohmann/json.hpp>

#include "io/json_text.hpp"

namespace needle::training {

std::string check_recording_identity(const std::string& file, const haptics::SessionHeader& header,
                                     const SessionInfo& info) {
  const std::string session = "session " + std::to_string(info.id);
  std::string recorded;
  if (!header.context.empty()) {
    nlohmann::json context;
    try {
      context = io::parse_json_text(header.context);
    } catch (const io::JsonTextError& e) {
      throw haptics::RecordingError(file + ": header: context: " + e.located());
    }
    if (context.is_object() && context.contains(kRecordingSessionKey) && context[kRecordingSessionKey].is_string())
      recorded = context[kRecordingSessionKey].get<std::string>();
  }
  if (recorded.empty() || info.uid.empty())
    return file + ": made before recordings named their session: that it is " + session + "'s cannot be checked";
  if (recorded != info.uid)
    throw haptics::RecordingError(file + ": the recording of another session (uid " + recorded + "), not of " +
                                  session + " (uid " + info.uid + "): refused");
  return "";
}

}  // namespace needle::training
