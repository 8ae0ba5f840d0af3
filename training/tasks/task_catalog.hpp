// The tasks a folder holds, for the start screen (docs/TASKS.md, "The start screen"): every task
// file with its title and one-line description, and every file that should be a task but does
// not load, with its error, so that a broken task is seen instead of missing.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "training/tasks/task.hpp"

namespace needle::training {

struct TaskEntry {
  std::filesystem::path file;
  std::string name, title, description;  // empty when the file does not load
  std::string error;                     // "FILE: /pointer: what is wrong" when it does not
  std::optional<int> order;              // the task's `order`, when it has one
};

// Every *.json in `folder` but the operator scripts (a top-level "hand": the <task>_good.json and
// <task>_sloppy.json beside each task): the tasks with an `order` first, lowest first, then the
// others (and the files that do not load) in file-name order. Throws TaskError naming the folder
// when it cannot be read.
std::vector<TaskEntry> find_tasks(const std::filesystem::path& folder);

}  // namespace needle::training
