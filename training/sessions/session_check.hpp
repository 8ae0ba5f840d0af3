// A session's stored results checked against the replay of its recording (needle-sim verify,
// docs/SESSIONS.md "Verifying scores"): what differs, the check's record in the store, and what the
// review shows of it. The replay is bit-exact, so every stored number must equal the replay's.
#pragma once

#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "training/scoring/session_scorer.hpp"

namespace needle::training {

struct StoredSession;
struct SessionInfo;

// What a check found: the stored results equal the replay's (verified), differ (mismatch), or the
// session could not be replayed (unverifiable: no recording, a damaged one, another session's...).
enum class CheckOutcome { kVerified, kMismatch, kUnverifiable };
const char* check_outcome_name(CheckOutcome outcome);
bool check_outcome_from_name(const std::string& name, CheckOutcome& outcome);

// One check as the store keeps it (session_checks): when, by whom (the login role on PostgreSQL,
// the user on SQLite), its outcome, the score it found stored and the digest of every stored
// result it checked, and what differed or why it could not replay (one line each, '\n' between).
struct SessionCheck {
  int64_t session_id = 0;
  CheckOutcome outcome = CheckOutcome::kUnverifiable;
  double score = NAN;
  std::string digest;
  std::string detail;
  std::string checked_at, checked_by;
};

// (stored, replay) => one line per difference, "" none: the score, passed, the duration, each
// step's id, outcome, start and end, each metric of each step and of the session, the score's
// breakdown; numbers compared bit for bit (a metric that does not apply, NaN, equals NaN).
std::vector<std::string> result_differences(const StoredSession& stored, const SessionResult& replay);

// (stored) => the CRC-32 (hex) of the text of everything above as stored: a check applies to the
// results it saw; another digest now means they changed since.
std::string result_digest(const StoredSession& stored);

// What the review shows of a complete session: verified (its latest check verified it and its score
// is the one checked), mismatch (the latest check found a difference, or the score changed since a
// check), unverified (never checked, or it could not be replayed).
enum class Verification { kUnverified, kVerified, kMismatch };
Verification verification(const SessionInfo& info);
const char* verification_word(Verification v);

// (a complete stored session, its latest check loaded) => the verdict and a line saying it: its
// results now are checked against the digest the check saw, so any change since shows.
struct VerificationStatus {
  Verification verdict = Verification::kUnverified;
  std::string line;
};
VerificationStatus verification_status(const StoredSession& stored);

}  // namespace needle::training
