// The `syringe` block of a scenario (docs/TISSUE.md, "The syringe"), read strictly through the
// project's JSON reader: "FILE: /syringe/...: what is wrong".
#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "haptics/syringe/syringe_model.hpp"
#include "haptics/tissue/tissue_model.hpp"

namespace needle::haptics {

// {"fluid": "saline" | "air"} and, optionally, any key of kSyringeFields (each in its range; absent,
// SyringeParams' value). The fluid goes into `tissue`, which must be layered and give every
// non-rigid layer its injection parameters: a layer without them is "FILE: /tissue/layers/N: ...".
// Throws ScenarioError.
SyringeParams read_syringe(const nlohmann::json& j, const std::string& file, const std::string& at,
                           const TissueModel& tissue);

}  // namespace needle::haptics
