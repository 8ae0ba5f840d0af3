// The stress sweeps of `needle-sim bench stability`, as scenario variants: gains ×0.1 … ×100,
// servo period ×1 … ×8, singular poses (arm stretched; wrist roll axis along the needle), an
// operator pushing at twice the device's force limit, sustained contact, and the penalty
// stiffness across the passivity bound K_crit = 2(b − |B|)/T (Colgate and Schenkel).
#pragma once

#include <string>
#include <vector>

#include "haptics/sim/scenario.hpp"

namespace needle::haptics {

struct StressCase {
  std::string name;   // sweep
  std::string value;  // the swept value, human-readable
  Scenario scenario;
};

// b: physical damping at the tip (the hand's), |B| = 0: the penalty's damping is applied
// implicitly by the virtual world, not rendered explicitly by the device.
double passivity_stiffness_bound(const Scenario& scenario);

// Every sweep built from the two thesis scenarios; the sustained-contact case lasts sustained_s.
std::vector<StressCase> stress_cases(const Scenario& holonomic, const Scenario& nonholonomic, double sustained_s);

// The sweeps of a layered scenario: every layer's puncture force, friction (dynamic and
// static) and surface stiffness (k₁, k₂) each ×0.1 … ×10, the period ×1 … ×8, and, when its
// tissue has a rigid layer, the hand pushing the needle onto it at twice the device's force limit.
std::vector<StressCase> layered_stress_cases(const Scenario& layered);

// Single sweeps, also used by tests.
Scenario with_gain_scale(Scenario s, double scale);
Scenario with_period_scale(Scenario s, double scale);
Scenario holding_pose(Scenario s, const VecN& q0, bool in_tissue);
Scenario pressing(Scenario s, double force_N, double hold_until_s);
// Every layer's mechanics through `change` (the model rebuilt: the same checks as a file's).
Scenario with_layer_mechanics(Scenario s, void (*change)(LayerMechanics&, double), double k);
// The scenario's script up to its third waypoint (on the surface), then the hand target driven along
// the needle to force_N / K_h beyond the first rigid layer on that line, held, and withdrawn.
Scenario pushing_onto_bone(Scenario s, double force_N);

}  // namespace needle::haptics
