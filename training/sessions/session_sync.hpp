// Sessions a station kept while it could not reach the server, sent when it can (needle-sim sync,
// docs/SESSIONS.md "Offline"). A session is found on the server by the uid its station made, so
// sending twice, or after a run that reached the server half-way, stores it once: what the server
// lacks (the session, the rest of its recording, its results) is added, nothing is repeated.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "training/sessions/session_store.hpp"

namespace needle::training {

// Stores `local` (a complete session) on `remote` with the recording bytes of `recording` the
// server does not have yet. Returns the session's id on the server.
int64_t send_session(const StoredSession& local, const std::filesystem::path& recording, SessionStore& remote);

struct SyncReport {
  std::vector<std::string> sent;    // "uid: local id L, server id S"
  std::vector<std::string> failed;  // "local id L: why"
};

// Sends every session of `local`'s outbox to `remote` and takes each sent one out of it.
// Recording paths are resolved beside `local_file`.
SyncReport sync_outbox(SessionStore& local, const std::filesystem::path& local_file, SessionStore& remote);

}  // namespace needle::training
