#include "training/tasks/scripted_operator.hpp"

#include <fstream>
#include <nlohmann/json.hpp>

#include "io/write_file.hpp"

namespace needle::training {
namespace fs = std::filesystem;
using nlohmann::json;

namespace {

json read_json(const fs::path& file) {
  std::ifstream in(file);
  if (!in) throw TaskError(file.string() + ": /: cannot read");
  try {
    return json::parse(in);
  } catch (const json::exception& e) {
    throw TaskError(file.string() + ": /: not valid JSON (" + e.what() + ")");
  }
}

}  // namespace

fs::path operator_script_path(const Task& task, const std::string& spec) {
  fs::path path = (spec == "good" || spec == "sloppy") ? fs::path(task.source).parent_path() / (task.name + "_" + spec + ".json")
                                                        : fs::path(spec);
  if (!fs::is_regular_file(path)) throw TaskError(path.string() + ": /: operator script not found");
  return path;
}

json task_scenario_json(const Task& task) {
  if (task.scenario.empty()) throw TaskError(task.source + ": /scenario: the task names no haptics scenario to run");
  json scenario = read_json(task.scenario);
  for (const char* key : {"master_urdf", "virtual_urdf"}) {  // relative to the task's scenario, not a copy
    if (!scenario.contains(key) || !scenario[key].is_string())
      throw TaskError(task.scenario.string() + ": /" + key + ": expected the robot's URDF file");
    scenario[key] = fs::absolute(task.scenario.parent_path() / scenario[key].get<std::string>()).string();
  }
  // A layered tissue's parameter files, relative to the scenario as well.
  if (scenario.contains("tissue") && scenario["tissue"].is_object() && scenario["tissue"].contains("layers") &&
      scenario["tissue"]["layers"].is_array()) {
    for (json& layer : scenario["tissue"]["layers"]) {
      if (layer.is_object() && layer.contains("parameters") && layer["parameters"].is_string())
        layer["parameters"] = fs::absolute(task.scenario.parent_path() / layer["parameters"].get<std::string>()).string();
    }
  }
  return scenario;
}

haptics::Scenario write_scenario(const json& scenario, const fs::path& file) {
  if (file.has_parent_path()) fs::create_directories(file.parent_path());
  io::write_file(file, scenario.dump(2) + "\n");
  return haptics::load_scenario(file.string());
}

haptics::Scenario scenario_with_operator(const Task& task, const fs::path& script, const fs::path& merged_file) {
  json scenario = task_scenario_json(task);
  const json operator_script = read_json(script);
  if (!operator_script.contains("hand") || !operator_script["hand"].contains("waypoints") ||
      !operator_script["hand"]["waypoints"].is_array() || operator_script["hand"]["waypoints"].empty()) {
    throw TaskError(script.string() + ": /hand/waypoints: expected a non-empty array of waypoints");
  }
  scenario["hand"] = operator_script["hand"];
  const json& last = operator_script["hand"]["waypoints"].back();
  if (!last.contains("t") || !last["t"].is_number()) {
    throw TaskError(script.string() + ": /hand/waypoints/" + std::to_string(operator_script["hand"]["waypoints"].size() - 1) +
                    "/t: expected a time in seconds");
  }
  scenario["duration_s"] = last["t"].get<double>() + 4.0;
  return write_scenario(scenario, merged_file);
}

}  // namespace needle::training
