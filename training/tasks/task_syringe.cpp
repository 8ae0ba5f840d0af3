#include "training/tasks/task_syringe.hpp"

#include "io/strict_json.hpp"
#include "training/tasks/task.hpp"

namespace needle::training {

const char* syringe_technique_name(SyringeTechnique technique) {
  return technique == SyringeTechnique::kIntermittent ? "intermittent" : "continuous";
}

TaskSyringe read_task_syringe(const nlohmann::json& j, const std::string& file, const std::string& at,
                              const std::vector<haptics::Scenario::NamedMechanics>& layers) {
  const io::StrictJsonReader<TaskError> r(file);
  r.object(j, at, {"fluid", "technique", "space"});
  TaskSyringe s;
  const std::string fluid = r.string(r.member(j, at, "fluid"), at + "/fluid");
  const auto named = haptics::parse_syringe_fluid(fluid.c_str());
  if (!named) r.fail(at + "/fluid", "expected \"saline\" or \"air\", got \"" + fluid + "\"");
  s.fluid = *named;
  const std::string technique = r.string(r.member(j, at, "technique"), at + "/technique");
  if (technique == "intermittent")
    s.technique = SyringeTechnique::kIntermittent;
  else if (technique != "continuous")
    r.fail(at + "/technique", "expected \"continuous\" or \"intermittent\", got \"" + technique + "\"");
  if (layers.size() < 2) r.fail(at, "a syringe needs the scenario's layered tissue (/scenario)");
  std::string names;
  for (const haptics::Scenario::NamedMechanics& layer : layers) {
    if (layer.mechanics.rigid) continue;
    if (!layer.injection)
      r.fail(at, "the scenario's layer \"" + layer.name + "\" has no injection parameters, which the syringe needs");
    names += (names.empty() ? "\"" : ", \"") + layer.name + "\"";
  }
  const std::string space = r.string(r.member(j, at, "space"), at + "/space");
  for (size_t i = 0; i < layers.size(); ++i)
    if (layers[i].name == space && !layers[i].mechanics.rigid) s.space = int(i);
  if (s.space < 0)
    r.fail(at + "/space", "no soft layer named \"" + space + "\" in the scenario's tissue (its layers: " + names + ")");
  return s;
}

}  // namespace needle::training
