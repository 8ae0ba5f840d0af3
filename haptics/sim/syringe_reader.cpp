#include "haptics/sim/syringe_reader.hpp"

#include "haptics/sim/scenario.hpp"
#include "io/strict_json.hpp"

namespace needle::haptics {

SyringeParams read_syringe(const nlohmann::json& j, const std::string& file, const std::string& at,
                           const TissueModel& tissue) {
  const io::StrictJsonReader<ScenarioError> r(file);
  std::vector<const char*> keys{"fluid"};
  for (const auto& f : kSyringeFields) keys.push_back(f.key);
  r.object(j, at, keys);
  SyringeParams p;
  const std::string fluid = r.string(r.member(j, at, "fluid"), at + "/fluid");
  const auto named = parse_syringe_fluid(fluid.c_str());
  if (!named) r.fail(at + "/fluid", "expected \"saline\" or \"air\", got \"" + fluid + "\"");
  p.fluid = *named;
  for (const auto& f : kSyringeFields)
    if (j.contains(f.key)) p.*f.member = r.number(j[f.key], at + "/" + f.key);
  if (const auto problem = syringe_problem(p)) r.fail(at + "/" + problem->key, problem->what);
  if (tissue.empty() || !tissue.has_axial_mechanics())
    r.fail(at, "a syringe needs a layered tissue (/tissue/layers) whose layers say what they do to an injection");
  for (int i = 0; i < tissue.layer_count(); ++i) {
    const TissueLayer& layer = tissue.layer(i);
    if (!layer.mechanics.rigid && !layer.injection)
      r.fail("/tissue/layers/" + std::to_string(i),
             "\"" + layer.name +
                 "\" has no injection parameters (\"injection\", in its parameter set or inline), which the syringe (" +
                 at + ") needs");
  }
  return p;
}

}  // namespace needle::haptics
