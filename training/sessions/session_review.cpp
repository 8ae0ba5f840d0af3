#include "training/sessions/session_review.hpp"

#include "haptics/recording/session_format.hpp"
#include "io/file_write.hpp"
#include "training/sessions/recording_identity.hpp"

namespace needle::training {
namespace fs = std::filesystem;

fs::path resolve_recording(const fs::path& db_file, const std::string& recording_path) {
  const fs::path given(recording_path);
  if (given.is_absolute()) return given;
  const fs::path beside_db = fs::absolute(db_file).parent_path() / given;
  if (!fs::exists(beside_db) && fs::exists(given)) return fs::absolute(given);
  return beside_db;
}

fs::path fetch_stored_recording(const SessionStore& store, const SessionInfo& info) {
  const std::optional<std::string> bytes = store.recording(info.id);
  if (!bytes) return {};
  const std::string uid = info.uid.empty() ? std::to_string(info.id) : info.uid;
  const fs::path file = fs::temp_directory_path() / ("needle-sim-recording-" + uid + ".nrec");
  io::write_file(file, *bytes);
  return file;
}

fs::path locate_recording(const SessionStore& store, const fs::path& db_file, const SessionInfo& info,
                          fs::path& fetched) {
  // A server's session carries its recording; a file's names it beside the file.
  if (store.engine() == SqlEngine::kPostgres) fetched = fetch_stored_recording(store, info);
  return fetched.empty() ? resolve_recording(db_file, info.recording_path) : fetched;
}

SessionReview load_session_review(const SessionStore& store, const fs::path& db_file, int64_t id) {
  SessionReview r;
  r.stored = store.load(id);
  const SessionInfo& info = r.stored.info;
  if (info.task_source.empty()) {
    r.task_problem = "the database names no file for task " + info.task;
  } else {
    try {
      r.task = load_task(info.task_source);
    } catch (const std::exception& e) {
      r.task_problem = e.what();
    }
  }
  std::vector<haptics::TickSample> samples;
  if (info.recording_path.empty()) {
    r.recording_problem = "no recording (the session was stored without one)";
  } else {
    fs::path fetched;  // the server's copy, read then removed: the review keeps the samples
    try {
      r.recording_file = locate_recording(store, db_file, info, fetched);
      haptics::Session session = haptics::read_session(r.recording_file.string());
      const std::string unchecked = check_recording_identity(r.recording_file.string(), session.header, info);
      samples = std::move(session.records);
      r.recording_end = session.end;
      r.recording_notes = haptics::recording_notes(r.recording_file.string(), session.end, samples.size());
      if (!unchecked.empty()) r.recording_notes.push_back(unchecked);
      r.loop = loop_health(samples, session.header.rate_hz);
      if (samples.empty()) r.recording_problem = r.recording_file.string() + ": the recording has no samples";
    } catch (const std::exception& e) {
      r.recording_problem = e.what();
      if (!r.recording_file.empty() && !fs::exists(r.recording_file))
        r.recording_problem = r.recording_file.string() + ": recording not found";
    }
    std::error_code ignored;
    if (!fetched.empty()) fs::remove(fetched, ignored);
  }
  r.plots = session_plots(samples, r.task ? &*r.task : nullptr);
  if (!r.has_recording()) {
    for (Plot* p : {&r.plots.force, &r.plots.lateral, &r.plots.depth, &r.plots.tracking})
      p->missing = r.recording_problem;
  } else if (!r.task) {
    r.plots.depth.missing = r.task_problem;
  }
  r.force_depth = force_depth(samples, r.task ? &*r.task : nullptr);
  if (!r.has_recording()) r.force_depth.plot.missing = r.recording_problem;
  r.states.reserve(samples.size());
  for (const haptics::TickSample& s : samples) r.states.push_back(s.state);
  return r;
}

}  // namespace needle::training
