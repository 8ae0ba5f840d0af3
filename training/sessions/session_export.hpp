// A session's metrics and per-step results as JSON and CSV: what `needle-sim report` writes,
// and (result_json) the run's score.json. Formats in docs/SESSIONS.md, "Export".
#pragma once

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "training/scoring/session_scorer.hpp"
#include "training/sessions/session_store.hpp"

namespace needle::training {

// {"score", "passed", "reasons_failed", "components", "metrics", "steps"}; NaN is null.
nlohmann::json result_json(const SessionResult& result);
// The same keys for a stored session, plus "session" (who, what, when, device, recording).
nlohmann::json session_json(const StoredSession& session);
// Long format, one row per metric: session_id,step_index,step_id,outcome,start_s,end_s,metric,value
// (step_index -1 and step_id "session" for the whole session; empty value: does not apply).
std::string session_csv(const StoredSession& session);

// A layered session's punctures, one row each:
// session_id,index,layer,t_s,depth_m,peak_force_N (index from 0, in order).
std::string punctures_csv(int64_t session_id, const std::vector<PunctureResult>& punctures);

// Writes session_<id>.json and session_<id>.csv into `dir` (created if needed); returns the
// JSON's path, each file written whole (io::write_file). With `punctures` (a layered session's,
// from its recording: the store does not keep them) the JSON gains "punctures" (score.json's form)
// and session_<id>_punctures.csv is written. Throws std::runtime_error naming the folder, or
// io::WriteError naming the file, when it cannot write.
std::filesystem::path export_session(const StoredSession& session, const std::filesystem::path& dir,
                                     const std::vector<PunctureResult>* punctures = nullptr);

}  // namespace needle::training
