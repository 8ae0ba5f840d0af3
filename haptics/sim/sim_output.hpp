// Files of `needle-sim simulate`: the per-tick CSV and summary.json. Not for the servo loop.
#pragma once

#include <string>

#include "haptics/sim/closed_loop.hpp"

namespace needle::haptics {

// Header: t, q_m1..n, q_v1..n, x_m_x..z, x_v_x..z, F_h_x..z, F_v_x..z, lambda_v1..2,
// lambda_m1..2, phi, psi1..2, energy, mode, axial_force_N, layer (the name of the tissue layer holding
// the tip, empty in none). SI units, world frame. Each file is written whole (io::write_file);
// io::WriteError names the file when it cannot be.
void write_ticks_csv(const std::string& path, const std::vector<TickRecord>& ticks, int dof, const TissueModel& tissue);
void write_summary_json(const std::string& path, const SimSummary& summary);

}  // namespace needle::haptics
