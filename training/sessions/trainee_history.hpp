// What the start screen shows of the trainees' past sessions, from the store's list: the names
// it knows, and a trainee's last and best score per task.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "training/sessions/session_store.hpp"

namespace needle::training {

// Every trainee in `sessions` (the store's list, newest first) once, the most recent first.
std::vector<std::string> known_trainees(const std::vector<SessionInfo>& sessions);

struct TaskHistory {
  SessionInfo last;   // the newest complete session
  int completed = 0;  // complete sessions
  double best = 0.0;  // their best score
};

// The trainee's complete sessions by task (Task::name); tasks never completed are absent.
std::map<std::string, TaskHistory> task_history(const std::vector<SessionInfo>& sessions, const std::string& trainee);

}  // namespace needle::training
