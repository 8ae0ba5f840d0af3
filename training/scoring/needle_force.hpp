// The world's force on the needle by what makes it, in the scene's newtons, and what the hand feels
// of it through the device (docs/SCORING.md, "Forces"). The trainee's gauge, the metrics and the
// review's plots read these, one definition for all.
#pragma once

#include "haptics/realtime/tool_snapshot.hpp"

namespace needle::training {

// The tissue's sideways reaction now: |lambda| of the nonholonomic multipliers (thesis 3.22)
// while in tissue, 0 elsewhere (N). The integrand of lateral_load_Ns (docs/SCORING.md).
double lateral_load_N(const haptics::ToolSnapshot& state);

struct NeedleForce {
  double along_N = 0.0;     // the tissue's axial force: cutting, friction, a surface tented (> 0 resists the advance)
  double sideways_N = 0.0;  // the tissue's hold across the needle (lateral_load_N)
  double rigid_N = 0.0;     // the rigid contact: bone or the rigid surface (|F_v|, thesis 3.16)
  double total_N = 0.0;     // |along·x₅ + sideways + F_v|: the sideways hold is across x₅
};

// (state) => the needle's force by part; total_N as vectors, the axial force along the needle axis
// x₅, the sideways hold at right angles to it, the rigid contact as F_v.
NeedleForce needle_force(const haptics::ToolSnapshot& state);

// (state, force scale s) => s·total_N: the world's force as the device renders it to the hand,
// newtons at the hand (the scenario's gains.force_scale, 1 but where tissue forces exceed the
// device's; the tool's weight and the controller's own damping aside).
inline double hand_force_N(const haptics::ToolSnapshot& state, double force_scale) {
  return force_scale * needle_force(state).total_N;
}

}  // namespace needle::training
