// The review's table of sessions without ImGui: which rows a text filter keeps and in what
// order the sort columns put them (docs/REVIEW.md, "Session table"). The ImGui table hands its
// sort specs and filter text here, so the rules are tested without a display.
#pragma once

#include <string>
#include <vector>

#include "training/sessions/session_store.hpp"

namespace needle::training {

enum class SessionColumn { kId, kTrainee, kTask, kDate, kScore, kDuration, kResult, kCheck };

struct SessionSort {
  SessionColumn column = SessionColumn::kId;
  bool descending = false;
};

// "passed", "failed" or "incomplete" (an incomplete session has no score).
const char* session_result_word(const SessionInfo& s);

// "verified", "mismatch" or "unverified" for a complete session (its latest check against its
// recording, session_check.hpp), "" for an incomplete one.
const char* session_check_word(const SessionInfo& s);

// True when every whitespace-separated term of `filter` occurs (ignoring case) in the session's
// trainee, task, date, device, result word or check word, and no term written "-term" does. Empty: all.
bool session_matches(const SessionInfo& s, const std::string& filter);

// Indices into `sessions` of the rows the filter keeps, ordered by the sort columns in priority
// order (a stable sort; ties keep the store's order, newest first). An incomplete session has
// no score: it sorts after every scored one in either direction.
std::vector<size_t> session_rows(const std::vector<SessionInfo>& sessions, const std::string& filter,
                                 const std::vector<SessionSort>& sort);

}  // namespace needle::training
