// Whose recording a file is: a recording keeps the uid of the session it was recorded for (its
// context's session_uid, app/session_rig.cpp), checked against the session the store says it
// belongs to, so that a session is never reviewed, reported or verified with another's recording.
#pragma once

#include <string>

#include "haptics/recording/session_format.hpp"
#include "training/sessions/session_store.hpp"

namespace needle::training {

// The key of a recording's context that holds the uid of its session (SessionInfo::uid).
inline constexpr const char* kRecordingSessionKey = "session_uid";

// (the recording `file`, its header, the stored session `info`) => "" when the recording names
// `info`'s session, else a note that it cannot be told (a recording, or a session, from before they
// kept uids). Throws haptics::RecordingError naming the store's session and the file when the
// recording names another session, or its context is not JSON.
std::string check_recording_identity(const std::string& file, const haptics::SessionHeader& header,
                                     const SessionInfo& info);

}  // namespace needle::training
