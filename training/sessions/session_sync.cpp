#include "training/sessions/session_sync.hpp"

#include <fstream>

#include "training/sessions/session_review.hpp"

namespace needle::training {

namespace fs = std::filesystem;

int64_t send_session(const StoredSession& local, const fs::path& recording, SessionStore& remote) {
  const SessionInfo& info = local.info;
  if (info.uid.empty())
    throw SessionStoreError(remote.name() + ": session " + std::to_string(info.id) + " has no uid to send it by");
  const std::optional<SessionInfo> found = remote.find_uid(info.uid);
  if (found && found->complete) return found->id;
  const int64_t id =
      found ? found->id
            : remote.begin_session({info.trainee, info.task, info.task_title, info.task_source, info.device,
                                    info.recording_path, info.station, info.uid, info.started_at});
  if (!recording.empty()) {
    std::ifstream in(recording, std::ios::binary);
    if (!in) throw SessionStoreError(recording.string() + ": cannot read the recording to send it");
    int64_t offset = remote.recording_bytes(id);
    in.seekg(offset);
    std::string chunk(size_t(1) << 20, '\0');  // a MiB a chunk
    while (in.read(chunk.data(), std::streamsize(chunk.size())) || in.gcount() > 0) {
      const std::string bytes = chunk.substr(0, size_t(in.gcount()));
      remote.append_recording(id, offset, bytes);
      offset += int64_t(bytes.size());
    }
  }
  remote.finish_session(id, stored_result(local), info.ended_at);
  return id;
}

SyncReport sync_outbox(SessionStore& local, const fs::path& local_file, SessionStore& remote) {
  SyncReport report;
  for (const int64_t local_id : local.outbox()) {
    try {
      const StoredSession stored = local.load(local_id);
      const fs::path recording =
          stored.info.recording_path.empty() ? fs::path() : resolve_recording(local_file, stored.info.recording_path);
      const int64_t remote_id = send_session(stored, recording, remote);
      local.sent(local_id);
      report.sent.push_back(stored.info.uid + ": local id " + std::to_string(local_id) + ", server id " +
                            std::to_string(remote_id));
    } catch (const std::exception& e) {
      report.failed.push_back("local id " + std::to_string(local_id) + ": " + e.what());
    }
  }
  return report;
}

}  // namespace needle::training
