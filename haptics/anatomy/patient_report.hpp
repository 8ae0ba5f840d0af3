// What `needle-sim patient` reports of a generated patient (DIR/patient.json, docs/PATIENTS.md):
// the patient, each vertebra's dimensions, and per interspace the depths a midline needle meets,
// measured on the fields themselves along the approach (haptics/anatomy/patient.hpp).
#pragma once

#include <nlohmann/json.hpp>
#include <optional>

#include "haptics/anatomy/patient.hpp"

namespace needle::haptics::anatomy {

// The depths along an interspace's midline approach, from where it meets the skin; nothing where
// the line does not reach that layer (a bone in the way).
struct ApproachDepths {
  std::optional<double> supraspinous_m, flavum_m, epidural_m, dura_m;
};
ApproachDepths approach_depths(const Patient& patient, const TissueModel& geometry, int interspace);

// {patient, bmi, vertebrae: [{level, body_height_m, spinous_process_length_m, interlaminar_gap_m,
// ...}], "L1-L2": {skin_to_epidural_m, supraspinous_to_epidural_m, skin_to_dura_m, ...}, ...,
// layers, tuffier_line}. Lengths in m, model frame; null where the approach meets no such layer.
nlohmann::json patient_report(const Patient& patient);

}  // namespace needle::haptics::anatomy
