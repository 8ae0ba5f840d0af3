// needle-sim verify as a command runs it (docs/SESSIONS.md, "Verifying scores"): the sessions chosen,
// verified on parallel threads (app/session_verify.hpp), a line said per session, the mismatches
// exported, each check kept in the store for the review to show.
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>

#include "app/messages.hpp"

namespace needle::app {

struct VerifyOptions {
  std::string db;                  // a file or a postgresql:// URI
  std::optional<int64_t> session;  // one session; nullopt: every complete session
  std::filesystem::path out;       // verify.json and verify_mismatches.csv go here
  int jobs = 1;                    // replays at once
  Messages messages;               // a line per session and the totals
};

// Verifies, says a line per session and the totals (sessions per minute), writes OUT/verify.json
// (every session's outcome, differences and notes) and OUT/verify_mismatches.csv (a row per
// difference or reason: session_id,outcome,what), and keeps each check in the store (said when the
// store cannot take them: a file it cannot write, a role without the right). Returns 0 when every
// session verified, 1 when one did not (a mismatch, or a session that could not be replayed).
// Throws a runtime error naming the database, or the session given that it lacks or that is
// incomplete.
int write_verify_report(const VerifyOptions& options);

}  // namespace needle::app
