// One session as the instructor's review shows it: what the store holds, the task it ran
// (markers for the depth plot, scene for the replay) and its recording turned into plots and
// replay states. A missing task file or recording is not an error here: the review shows the
// metrics and says, naming the file, why there are no plots or replay (docs/REVIEW.md).
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "haptics/recording/session_format.hpp"
#include "training/sessions/force_depth.hpp"
#include "training/sessions/loop_health.hpp"
#include "training/sessions/session_series.hpp"
#include "training/sessions/session_store.hpp"

namespace needle::training {

struct SessionReview {
  StoredSession stored;
  std::optional<Task> task;
  std::string task_problem;                   // why `task` is empty
  std::filesystem::path recording_file;       // resolved; empty when the session names none
  std::vector<haptics::ToolSnapshot> states;  // the recorded states, for the replay
  std::string recording_problem;              // why `states` is empty ("no recording", unreadable...)
  haptics::RecordingEnd recording_end;        // closed, or cut short (the run was killed), or unchecked
  std::vector<std::string> recording_notes;   // what to tell the reader about it (haptics::recording_notes)
  LoopHealth loop;                            // how the haptic loop kept time while it recorded
  SessionPlots plots;
  ForceDepth force_depth;  // a layered task's axial force against depth and its punctures (docs/REVIEW.md)

  bool has_recording() const { return recording_problem.empty(); }
  // Whether the task runs on a layered tissue: the review has the force–depth plot.
  bool layered() const { return task && task->layers.size() > 1; }
  bool has_syringe() const { return task && task->syringe.has_value(); }
  // A layered session's punctures, from its recording (the store does not keep them), for the
  // export; null for any other session.
  const std::vector<PunctureResult>* punctures() const {
    return layered() && has_recording() ? &force_depth.puncture_list : nullptr;
  }
  double start_s() const { return states.empty() ? 0.0 : states.front().time_s; }
  double end_s() const { return states.empty() ? 0.0 : states.back().time_s; }
};

// A session's recording path as stored, made absolute: a relative one is taken relative to the
// database's folder (where runs keep recordings/), else to the current folder when only it exists.
std::filesystem::path resolve_recording(const std::filesystem::path& db_file, const std::string& recording_path);

// The recording a session keeps in the database (PostgreSQL), every chunk checked, written to a
// file of the temporary folder named by its uid, for the recording's own reader to check and read;
// an empty path when the database holds none. Throws SessionStoreError for a damaged chunk.
std::filesystem::path fetch_stored_recording(const SessionStore& store, const SessionInfo& info);

// Where session `info`'s recording is read: the database's copy (PostgreSQL; fetched into the
// temporary folder, `fetched` then naming it for the caller to remove once read), else the file the
// session names, resolved beside `db_file`. Throws SessionStoreError for a damaged chunk.
std::filesystem::path locate_recording(const SessionStore& store, const std::filesystem::path& db_file,
                                       const SessionInfo& info, std::filesystem::path& fetched);

// Loads session `id` (SessionStoreError when there is none) with its task and recording: from the
// database when it holds the recording (PostgreSQL; the fetched file is removed once read), else
// the file the session names.
SessionReview load_session_review(const SessionStore& store, const std::filesystem::path& db_file, int64_t id);

}  // namespace needle::training
