// A task done by a scripted operator: the task's haptics scenario with its hand replaced by the
// operator's script (assets/tasks/<task>_good.json, <task>_sloppy.json, or a file), which the
// simulated device (`needle-sim run --device sim`) plays through the haptic loop.
#pragma once

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "haptics/sim/scenario.hpp"
#include "training/tasks/task.hpp"

namespace needle::training {

// "good" and "sloppy" name the task's own scripts; anything else is a script file.
// TaskError when the file does not exist.
std::filesystem::path operator_script_path(const Task& task, const std::string& spec);

// The task's haptics scenario as JSON, its robot files made absolute so it can be written
// anywhere; a generated patient inline (patient_session.hpp: `seed` draws a task's random patient).
// TaskError when the task names no scenario or the file is not JSON.
nlohmann::json task_scenario_json(const Task& task, uint64_t seed = 0);

// Writes a scenario's JSON to `file` (kept beside the run's results: what exactly ran) and loads
// it from there.
haptics::Scenario write_scenario(const nlohmann::json& scenario, const std::filesystem::path& file);

// The task's scenario with the script's hand, running until kScriptEnd_s after its last waypoint
// (at most io::kMaxSessionSeconds), written to `merged_file` by write_scenario. The script is read
// strictly first (TaskError naming the script and the JSON pointer).
inline constexpr double kScriptEnd_s = 4.0;
haptics::Scenario scenario_with_operator(const Task& task, const std::filesystem::path& script,
                                         const std::filesystem::path& merged_file, uint64_t seed = 0);

}  // namespace needle::training
