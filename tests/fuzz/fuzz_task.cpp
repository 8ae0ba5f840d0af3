// Task files (training::parse_task, as a replay reads the task its recording keeps, and load_task
// with the same text): any input is a task or a training::TaskError, nothing else.
#include "fuzz_input.hpp"
#include "structure.hpp"
#include "training/tasks/task.hpp"

NEEDLE_FUZZ_MUTATIONS(needle::fuzz::extreme_number, needle::fuzz::deep_json)

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    needle::training::parse_task(text, needle::fuzz::workdir() / "tasks" / "fuzz_input.json");
  } catch (const needle::training::TaskError&) {
  }
  try {
    needle::training::load_task(needle::fuzz::write_input("tasks/fuzz_input.json", data, size));
  } catch (const needle::training::TaskError&) {
  }
  return 0;
}
