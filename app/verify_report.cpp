#include "app/verify_report.hpp"

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <nlohmann/json.hpp>

#include "app/default_db.hpp"
#include "app/session_verify.hpp"
#include "io/file_write.hpp"
#include "training/sessions/export_format.hpp"
#include "training/sessions/store_location.hpp"

namespace needle::app {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

// The check's lines: what differed, or why it could not be replayed.
std::vector<std::string> lines_of(const std::string& detail) {
  std::vector<std::string> out;
  for (size_t at = 0; at < detail.size();) {
    const size_t end = std::min(detail.find('\n', at), detail.size());
    out.push_back(detail.substr(at, end - at));
    at = end + 1;
  }
  return out;
}

void report_session(const Messages& messages, const VerifiedSession& v) {
  const training::SessionCheck& c = v.check;
  const std::string head =
      formatted("session %lld: %s", static_cast<long long>(c.session_id),
                c.outcome == training::CheckOutcome::kMismatch ? "MISMATCH" : training::check_outcome_name(c.outcome));
  if (c.outcome == training::CheckOutcome::kUnverifiable) {
    messages.say(head + ": " + c.detail);
  } else {
    messages.say(head + formatted(" (checked in %.1f s)", v.replay_s));
    for (const std::string& line : lines_of(c.detail)) messages.say("  " + line);
  }
  for (const std::string& note : v.notes) messages.say("  note: " + note);
}

}  // namespace

int write_verify_report(const VerifyOptions& options) {
  std::vector<int64_t> ids;
  {
    const std::unique_ptr<training::SessionStore> store = open_existing_db(options.db);
    const std::vector<training::SessionInfo> sessions = store->sessions();
    for (const training::SessionInfo& s : sessions) {
      if (options.session && s.id != *options.session) continue;
      if (options.session && !s.complete)
        throw std::runtime_error(store->name() + ": session " + std::to_string(s.id) +
                                 " is incomplete: its run ended before the task did, and there is no score to verify");
      if (s.complete) ids.push_back(s.id);
    }
    if (options.session && ids.empty())
      throw std::runtime_error(store->name() + ": no session " + std::to_string(*options.session));
    std::sort(ids.begin(), ids.end());
    options.messages.say(formatted("verifying %zu complete session%s of %s against their recordings, %d at a time",
                                   ids.size(), ids.size() == 1 ? "" : "s", store->name().c_str(), options.jobs));
  }
  const auto t0 = std::chrono::steady_clock::now();
  const std::vector<VerifiedSession> results = verify_sessions(
      options.db, ids, options.jobs, [&](const VerifiedSession& v) { report_session(options.messages, v); });
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();

  size_t counts[3] = {0, 0, 0};
  json sessions = json::array();
  std::string csv = "session_id,outcome,what\n";
  for (const VerifiedSession& v : results) {
    const training::SessionCheck& c = v.check;
    ++counts[size_t(c.outcome)];
    const std::vector<std::string> lines = lines_of(c.detail);
    sessions.push_back(
        {{"id", c.session_id},
         {"outcome", training::check_outcome_name(c.outcome)},
         {"stored_score", training::json_number(c.score)},
         {"digest", c.digest},
         {"differences", c.outcome == training::CheckOutcome::kMismatch ? lines : std::vector<std::string>{}},
         {"problem", c.outcome == training::CheckOutcome::kUnverifiable ? c.detail : ""},
         {"notes", v.notes},
         {"replay_s", v.replay_s}});
    for (const std::string& line : lines)
      csv += std::to_string(c.session_id) + "," + training::check_outcome_name(c.outcome) + "," +
             training::csv_field(line) + "\n";
  }
  const double per_minute = seconds > 0.0 ? double(results.size()) / seconds * 60.0 : 0.0;
  const json report{{"db", training::shown_location(options.db)},
                    {"sessions", sessions},
                    {"verified", counts[0]},
                    {"mismatch", counts[1]},
                    {"unverifiable", counts[2]},
                    {"seconds", seconds},
                    {"sessions_per_min", per_minute},
                    {"jobs", options.jobs}};
  io::make_folder(options.out);
  io::write_file(options.out / "verify.json", report.dump(2) + "\n");
  io::write_file(options.out / "verify_mismatches.csv", csv);

  // Kept in the store for the review (sessions table, detail): a failure to keep them is said, and
  // changes nothing of what was found.
  std::string kept = "the checks are kept in the store";
  try {
    training::SessionStore store(options.db);
    const char* user = std::getenv("USER");  // SQLite's record of who checked (PostgreSQL: the login role)
    for (const VerifiedSession& v : results) {
      training::SessionCheck check = v.check;
      check.checked_by = user ? user : "";
      store.record_check(check);
    }
  } catch (const std::exception& e) {
    kept = std::string("the checks could not be kept in the store: ") + e.what();
  }
  options.messages.say(formatted(
      "%zu verified, %zu mismatch, %zu unverifiable of %zu complete session%s in %.1f s (%.1f sessions per minute); "
      "wrote %s and %s; %s",
      counts[0], counts[1], counts[2], results.size(), results.size() == 1 ? "" : "s", seconds, per_minute,
      (options.out / "verify.json").c_str(), (options.out / "verify_mismatches.csv").c_str(), kept.c_str()));
  return counts[0] == results.size() ? 0 : 1;
}

}  // namespace needle::app
