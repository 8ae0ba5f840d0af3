#include "training/scoring/needle_force.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace needle::training {

double lateral_load_N(const haptics::ToolSnapshot& state) {
  if (state.contact != haptics::ContactState::kTissue) return 0.0;
  double sum = 0.0;
  for (uint32_t i = 0; i < std::min<uint32_t>(state.multiplier_count, haptics::kMaxMultipliers); ++i)
    sum += state.multipliers[i] * state.multipliers[i];
  return std::sqrt(sum);
}

NeedleForce needle_force(const haptics::ToolSnapshot& state) {
  NeedleForce f;
  f.along_N = state.tissue.axial_force_N;
  f.sideways_N = lateral_load_N(state);
  const double* rigid = state.environment_force_n;
  f.rigid_N = std::sqrt(rigid[0] * rigid[0] + rigid[1] * rigid[1] + rigid[2] * rigid[2]);
  const std::array<double, 3> axis = haptics::needle_axis(state);
  double sum_sq = f.sideways_N * f.sideways_N;
  for (int i = 0; i < 3; ++i) {
    const double v = f.along_N * axis[size_t(i)] + rigid[i];
    sum_sq += v * v;
  }
  f.total_N = std::sqrt(sum_sq);
  return f;
}

}  // namespace needle::training
