// The patients a process has generated lately, kept so that reading a task's scenario again (to
// list its layers, to run it, to image it) does not generate the same patient again: generating is
// deterministic, so the kept one is the one that would be made. Thread-safe; never used in the tick.
#pragma once

#include <memory>

#include "haptics/anatomy/patient.hpp"

namespace needle::haptics::anatomy {

// The patient of these parameters placed at this entry, generated or kept (the last four).
std::shared_ptr<const Patient> shared_patient(const PatientParams& params, const Eigen::Vector3d& l3_l4_entry);

}  // namespace needle::haptics::anatomy
