// Scores verified from their recordings (needle-sim verify, docs/SESSIONS.md "Verifying scores"):
// a complete session's recording replayed through the task it recorded, as `run --device replay:`
// replays it (the same servo step, bit for bit), scored, and every stored number compared with the
// replay's. A score raised in the store, a step or a metric changed, a recording altered under valid
// checksums: each shows as a difference. A recording that cannot be replayed (none, damaged,
// another session's, cut short) leaves the session unverifiable.
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "training/sessions/session_store.hpp"

namespace needle::app {

// (a recording) => the result of its replay through the task its context keeps, scored as a run
// scores: the stored session's result when nothing was changed. `scratch`: a folder of the caller's
// for the scenario the replay writes. `task_name` is set to the replayed task's name. Throws
// haptics::RecordingError (damaged, cut short, no context), training::TaskError, ScenarioError.
training::SessionResult replay_result(const std::filesystem::path& recording, const std::filesystem::path& scratch,
                                      std::string& task_name);

struct VerifiedSession {
  training::SessionCheck check;    // outcome, the stored score, the digest it checked, detail
  std::vector<std::string> notes;  // what to tell beside it (an older recording whose owner cannot be told)
  double replay_s = 0.0;           // wall time of the replay
};

// Verifies session `id` of `store` (its recordings resolved beside `db`, as review does): the
// check's outcome and detail (what differed, one line each, or why it could not be replayed).
// Never throws for the session's own faults: a session that cannot be read is unverifiable.
VerifiedSession verify_session(const training::SessionStore& store, const std::filesystem::path& db, int64_t id);

// Verifies `ids` of the store at `location` on `jobs` threads, each with a connection of its own;
// `done` is called (one call at a time) as each finishes. Returns them in the order of `ids`.
std::vector<VerifiedSession> verify_sessions(const std::string& location, const std::vector<int64_t>& ids, int jobs,
                                             const std::function<void(const VerifiedSession&)>& done);

}  // namespace needle::app
