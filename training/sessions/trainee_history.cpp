#include "training/sessions/trainee_history.hpp"

#include <algorithm>

namespace needle::training {

std::vector<std::string> known_trainees(const std::vector<SessionInfo>& sessions) {
  std::vector<std::string> names;
  for (const SessionInfo& s : sessions)
    if (std::find(names.begin(), names.end(), s.trainee) == names.end()) names.push_back(s.trainee);
  return names;
}

std::map<std::string, TaskHistory> task_history(const std::vector<SessionInfo>& sessions, const std::string& trainee) {
  std::map<std::string, TaskHistory> history;
  for (const SessionInfo& s : sessions) {  // newest first: the first seen of a task is its last
    if (s.trainee != trainee || !s.complete) continue;
    auto [it, first] = history.try_emplace(s.task);
    TaskHistory& h = it->second;
    if (first) h.last = s;
    h.best = first ? s.score : std::max(h.best, s.score);
    ++h.completed;
  }
  return history;
}

}  // namespace needle::training
