// A stand-in for the haptic state until the loop drives the scene (and for benchmarks): the
// thesis's nonholonomic experiment on a sphere (section 4.4) as a function of time, repeating:
// approach, press a dimple, puncture and insert, pivot about the tip, insert deeper along the
// new direction, withdraw.
#pragma once

#include "engine/tissue.hpp"

namespace needle::engine {

struct ScriptedSphere {
  glm::dvec3 centre{0.4, 0.0, 0.0};
  double radius = 0.1;
  glm::dvec3 entry_direction{-1.0, 0.0, 0.35};  // from the centre to the entry point
  glm::dvec3 pivot_towards{0.0, 0.0, 1.0};      // the way the needle's hub swings
};

constexpr double kScriptPeriod_s = 12.0;

// The needle at time t (seconds, wrapped to the period).
NeedleLoad scripted_needle(const ScriptedSphere& sphere, double t_s);

}  // namespace needle::engine
