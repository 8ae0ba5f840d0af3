// A task on a generated patient as a session runs it (docs/TASKS.md, "Patients"): the patient the
// scenario is given (the scenario's own, the task's file, or one drawn at random for the attempt),
// written inline into the scenario a session records so that a replay, a verification and the review
// rebuild the same patient; and the landmarks of the patient that ran, for the guidance, the
// conditions and the metrics.
#pragma once

#include <cstdint>
#include <nlohmann/json.hpp>

#include "haptics/sim/scenario.hpp"
#include "training/tasks/task.hpp"

namespace needle::training {

// (task, the scenario's JSON with its paths absolute) => (its tissue's patient inline: the task's
// patient file, or for "random" the patient random_patient(seed) draws, or the scenario's own file
// read; its tissues folder absolute). Nothing for a scenario on no patient. TaskError naming the
// patient file when it does not read.
void inline_patient(const Task& task, nlohmann::json& scenario, const std::filesystem::path& scenario_folder,
                    uint64_t seed);

// (scenario that runs) => the landmarks of its patient, world frame; nothing without one.
std::optional<PatientLandmarks> patient_landmarks(const haptics::Scenario& scenario);

// Sets task.landmarks from the scenario the session runs (every session on a patient does this before
// its scoring starts, so a random patient's landmarks are its own).
void apply_patient(Task& task, const haptics::Scenario& scenario);

}  // namespace needle::training
