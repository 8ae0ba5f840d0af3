// The context a task session keeps in its recording's header (SessionHeader::context, JSON): what
// a replay needs to rebuild the session (docs/SESSIONS.md, "Recordings"). Written by the app's
// rig; read here, checked and brought to the present: a recording made before a key existed is
// given the value its absence meant then, so it replays as it ran.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "haptics/recording/session_format.hpp"

namespace needle::haptics {

// 1: task (its file), device, scenario, coupling, safety_limits; 2: and task_text, the task
// file's text as the session ran it; and, added later without a new version (older readers ignore
// it, a recording without it reads as before), session_uid, the uid of the session it was recorded for,
// and practice, true for an untimed practice session (its steps' time limits lifted; absent: false).
inline constexpr int kRecordingContextVersion = 2;

// (the recording's path, its header) => its context: an object of version
// kRecordingContextVersion with "task" and "task_text" (text), "scenario" and "safety_limits",
// "coupling" (null: joint to joint), "practice" (true or false). Migrated: scenario "gains" without "law" were recorded
// with the thesis law, without "lateral_stiffness_N_per_m", "axial_stiffness_N_per_m" or
// "passivity_max_damping_per_tick" without those springs or that controller (0); a "coupling" without "wrist" had none
// (false). Throws RecordingError "FILE: header: ..." for a header of format 1 or 2, or a context that is missing, not
// JSON, of another version or without those keys.
nlohmann::json read_recording_context(const std::string& path, const SessionHeader& header);

}  // namespace needle::haptics
