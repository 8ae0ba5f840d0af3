#include "training/tasks/scripted_operator.hpp"

#include <algorithm>
#include <nlohmann/json.hpp>

#include "io/file_write.hpp"
#include "io/input_limits.hpp"
#include "io/strict_json.hpp"
#include "training/tasks/patient_session.hpp"

namespace needle::training {
namespace fs = std::filesystem;
using nlohmann::json;

fs::path operator_script_path(const Task& task, const std::string& spec) {
  fs::path path = (spec == "good" || spec == "sloppy")
                      ? fs::path(task.source).parent_path() / (task.name + "_" + spec + ".json")
                      : fs::path(spec);
  if (!fs::is_regular_file(path)) throw TaskError(path.string() + ": /: operator script not found");
  return path;
}

json task_scenario_json(const Task& task, uint64_t seed) {
  if (task.scenario.empty()) throw TaskError(task.source + ": /scenario: the task names no haptics scenario to run");
  json scenario = io::read_json_file<TaskError>(task.scenario);
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
        layer["parameters"] =
            fs::absolute(task.scenario.parent_path() / layer["parameters"].get<std::string>()).string();
    }
  }
  inline_patient(task, scenario, task.scenario.parent_path(), seed);
  // The task's syringe on the needle: its fluid, the syringe's other numbers the scenario's own or the defaults.
  if (task.syringe) {
    if (!scenario.contains("syringe") || !scenario["syringe"].is_object()) scenario["syringe"] = json::object();
    scenario["syringe"]["fluid"] = haptics::syringe_fluid_name(task.syringe->fluid);
  }
  return scenario;
}

haptics::Scenario write_scenario(const json& scenario, const fs::path& file) {
  if (file.has_parent_path()) io::make_folder(file.parent_path());
  io::write_file(file, scenario.dump(2) + "\n");
  return haptics::load_scenario(file.string());
}

haptics::Scenario scenario_with_operator(const Task& task, const fs::path& script, const fs::path& merged_file,
                                         uint64_t seed) {
  json scenario = task_scenario_json(task, seed);
  // The script is read strictly here, so its errors name it and not the merged scenario.
  const json operator_script = io::read_json_file<TaskError>(script);
  const io::StrictJsonReader<TaskError> reader(script.string());
  reader.object(operator_script, "", {"description", "hand"});
  if (operator_script.contains("description")) reader.string(operator_script["description"], "/description");
  const json& hand = reader.member(operator_script, "", "hand");
  double end_s = 0.0;
  try {
    const haptics::OperatorHand read = haptics::read_hand(hand, script.string(), "/hand", Eigen::Vector3d::Zero());
    end_s = read.trajectory.end_time();
    // A reaction to the loss of resistance may come as late as the script's end, and lasts its waypoints.
    if (read.thumb && read.thumb->on_loss) end_s += read.thumb->on_loss->waypoints.back().t;
    if (read.thumb && !task.syringe)
      throw TaskError(script.string() + ": /hand/thumb: the task " + task.name +
                      " has no syringe for the thumb to press");
  } catch (const haptics::ScenarioError& e) {
    throw TaskError(e.what());  // already "SCRIPT: /hand/...: what"
  }
  scenario["hand"] = hand;
  scenario["duration_s"] = std::min(end_s + kScriptEnd_s, io::kMaxSessionSeconds);
  return write_scenario(scenario, merged_file);
}

}  // namespace needle::training
