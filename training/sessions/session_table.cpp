#include "training/sessions/session_table.hpp"

#include <algorithm>
#include <cctype>
#include <sstream>

namespace needle::training {
namespace {

std::string lower(std::string s) {
  for (char& c : s) c = char(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

// -1, 0 or 1 as a is before, level with or after b in ascending order; scores of incomplete
// sessions compare as missing, which the caller puts last.
int compare(const SessionInfo& a, const SessionInfo& b, SessionColumn column) {
  auto three_way = [](const auto& x, const auto& y) { return x < y ? -1 : y < x ? 1 : 0; };
  switch (column) {
    case SessionColumn::kId:
      return three_way(a.id, b.id);
    case SessionColumn::kTrainee:
      return three_way(lower(a.trainee), lower(b.trainee));
    case SessionColumn::kTask:
      return three_way(lower(a.task), lower(b.task));
    case SessionColumn::kDate:
      return three_way(a.started_at, b.started_at);  // ISO 8601 UTC sorts as text
    case SessionColumn::kScore:
      return three_way(a.score, b.score);
    case SessionColumn::kDuration:
      return three_way(a.duration_s, b.duration_s);
    case SessionColumn::kResult:
      return three_way(std::string(session_result_word(a)), std::string(session_result_word(b)));
    case SessionColumn::kCheck:
      return three_way(std::string(session_check_word(a)), std::string(session_check_word(b)));
  }
  return 0;
}

}  // namespace

const char* session_result_word(const SessionInfo& s) {
  if (!s.complete) return "incomplete";
  return s.passed ? "passed" : "failed";
}

const char* session_check_word(const SessionInfo& s) { return s.complete ? verification_word(verification(s)) : ""; }

bool session_matches(const SessionInfo& s, const std::string& filter) {
  const std::string text = lower(s.trainee + "\n" + s.task + "\n" + s.started_at + "\n" + s.device + "\n" +
                                 session_result_word(s) + "\n" + session_check_word(s));
  std::istringstream terms(lower(filter));
  std::string term;
  while (terms >> term) {
    const bool exclude = term.size() > 1 && term[0] == '-';
    const bool found = text.find(exclude ? term.substr(1) : term) != std::string::npos;
    if (found == exclude) return false;
  }
  return true;
}

std::vector<size_t> session_rows(const std::vector<SessionInfo>& sessions, const std::string& filter,
                                 const std::vector<SessionSort>& sort) {
  std::vector<size_t> rows;
  for (size_t i = 0; i < sessions.size(); ++i) {
    if (session_matches(sessions[i], filter)) rows.push_back(i);
  }
  std::stable_sort(rows.begin(), rows.end(), [&](size_t i, size_t j) {
    const SessionInfo &a = sessions[i], &b = sessions[j];
    for (const SessionSort& s : sort) {
      if (s.column == SessionColumn::kScore && a.complete != b.complete) return a.complete;  // missing last
      const int c = compare(a, b, s.column);
      if (c != 0) return s.descending ? c > 0 : c < 0;
    }
    return false;
  });
  return rows;
}

}  // namespace needle::training
