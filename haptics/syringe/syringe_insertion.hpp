// The syringe on the insertion bench's drive (`needle-sim bench insertion --syringe`): the tip
// driven kinematically through the tissue (haptics/tissue/kinematic_insertion.hpp) while a thumb
// presses the plunger with a constant force, and where the fluid gave way (the losses of resistance).
#pragma once

#include <vector>

#include "haptics/syringe/syringe_model.hpp"
#include "haptics/tissue/kinematic_insertion.hpp"

namespace needle::haptics {

struct SyringeDrive {
  SyringeParams params;
  double plunger_force_N = 0.0;  // > 0
};

struct SyringeSample {
  double pressure_Pa = 0.0;  // in the barrel, gauge, at the end of the tick
  double travel_m = 0.0;     // the plunger from full
};

struct SyringeLoss {
  double depth_m = 0.0;  // of the tip in the tick the flow began (as InsertionPuncture's)
  int layer = -1;        // holding the tip then, −1 in none
  double pressure_before_Pa = 0.0, pressure_after_Pa = 0.0;  // haptics::LossOfResistance
};

struct SyringeInsertionRun {
  InsertionRun insertion;
  std::vector<SyringeSample> samples;  // one per tick, as insertion.samples
  std::vector<SyringeLoss> losses;     // in order
  double work_J = 0.0;                 // the thumb's work on the plunger
};

// (model, plan, drive) => (run). The thumb presses as a clinician with the continuous technique
// does: while the needle goes in (not while it is held or withdrawn), from the first tick the tip is
// in a layer that holds the plunger still under the force (its opening pressure at least force /
// area) on; when the plunger gives way it keeps pressing
// until the loss's pressure after is read (kLossSettle_s), then lets go, and presses again in the
// next layer that holds the plunger (a false loss in fat, then the ligaments; the epidural space,
// then the dura). Every non-rigid layer needs its injection parameters (std::invalid_argument
// naming the first without).
SyringeInsertionRun run_syringe_insertion(const TissueModel& model, const InsertionPlan& plan,
                                          const SyringeDrive& drive);

}  // namespace needle::haptics
