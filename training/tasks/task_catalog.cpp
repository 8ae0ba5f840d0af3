#include "training/tasks/task_catalog.hpp"

#include <algorithm>
#include <nlohmann/json.hpp>

#include "io/strict_json.hpp"

namespace needle::training {

namespace fs = std::filesystem;

std::vector<TaskEntry> find_tasks(const fs::path& folder) {
  std::vector<fs::path> files;
  std::error_code ec;
  for (fs::directory_iterator it(folder, ec), end; !ec && it != end; it.increment(ec))
    if (it->path().extension() == ".json") files.push_back(it->path());
  if (ec) throw TaskError(folder.string() + ": cannot list the tasks: " + ec.message());
  std::sort(files.begin(), files.end());
  std::vector<TaskEntry> entries;
  for (const fs::path& file : files) {
    TaskEntry entry;
    entry.file = file;
    try {
      const nlohmann::json root = io::read_json_file<TaskError>(file);
      if (root.is_object() && root.contains("hand")) continue;  // an operator script
      const Task task = load_task(file);
      entry.name = task.name;
      entry.title = task.title;
      entry.description = task.description;
      entry.order = task.order;
    } catch (const TaskError& e) {
      entry.error = e.what();
    }
    entries.push_back(std::move(entry));
  }
  // Ordered tasks before the rest; stable, so equal orders and the rest keep file-name order.
  std::stable_sort(entries.begin(), entries.end(), [](const TaskEntry& a, const TaskEntry& b) {
    return a.order.value_or(kMaxTaskOrder + 1) < b.order.value_or(kMaxTaskOrder + 1);
  });
  return entries;
}

}  // namespace needle::training
