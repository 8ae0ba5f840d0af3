// A task's loss-of-resistance syringe (docs/TASKS.md, "Syringe"): the fluid it is filled with, the
// technique the trainee presses it with, and the layer whose loss of resistance is the one sought
// (a loss anywhere else is a false loss). The session's scenario gets the syringe
// (training/tasks/scripted_operator.hpp, task_scenario_json); the physics is haptics/syringe/.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "haptics/sim/scenario.hpp"
#include "haptics/syringe/syringe_model.hpp"

namespace needle::training {

enum class SyringeTechnique {
  kContinuous,    // the plunger pressed all the while the needle advances (saline)
  kIntermittent,  // the plunger tapped between advances (air)
};
const char* syringe_technique_name(SyringeTechnique technique);

struct TaskSyringe {
  haptics::SyringeFluid fluid = haptics::SyringeFluid::kSaline;
  SyringeTechnique technique = SyringeTechnique::kContinuous;
  int space = -1;  // the scenario tissue's layer where the loss is sought (the epidural space)
};

// {"fluid": "saline" | "air", "technique": "continuous" | "intermittent", "space": LAYER} at `at` of
// `file`, read strictly (TaskError "FILE: /syringe/...: what"). The scenario tissue's layers (a
// layered tissue's or a generated patient's, in order) must all say what they do to an injection (a
// layer without is named), and `space` must be one of its non-rigid layers.
TaskSyringe read_task_syringe(const nlohmann::json& j, const std::string& file, const std::string& at,
                              const std::vector<haptics::Scenario::NamedMechanics>& layers);

}  // namespace needle::training
