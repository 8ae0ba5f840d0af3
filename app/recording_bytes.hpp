// A recording written again from what haptics::read_session returns, in the recorder's framing (its
// header, blocks of 256 records, the end mark, every checksum made anew): for a recording changed
// on purpose. bench store gives each stored copy of its session a recording that names that copy;
// tests forge recordings whose checksums all hold, to show that verify replays what they say.
#pragma once

#include <string>

#include "haptics/recording/session_format.hpp"

namespace needle::app {

// (a read recording) => its bytes, block for block as SessionRecorder writes them.
std::string encode_session(const haptics::Session& session);

// (a recording's context, a session uid) => the context naming that session
// (training::kRecordingSessionKey).
std::string context_for_session(const std::string& context, const std::string& uid);

}  // namespace needle::app
