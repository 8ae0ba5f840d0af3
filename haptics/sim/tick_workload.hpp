// The servo tick the real-time loop runs, set up in nonholonomic contact: a scenario is played
// until the needle is in the tissue, then tick() repeats the controller step (master model,
// tracking, multipliers, virtual integration) on the frozen measured input. For bench tick and
// the zero-allocation test.
#pragma once

#include <memory>

#include "haptics/sim/scenario.hpp"

namespace needle::haptics {

class TickWorkload {
 public:
  // Plays `scenario` (which must reach the tissue) for `settle_s` seconds; throws if the
  // needle is not in the tissue then.
  TickWorkload(const Scenario& scenario, double settle_s);
  const TickOutput& tick() { return tele_->step(input_); }
  const Teleoperation& teleoperation() const { return *tele_; }

 private:
  std::unique_ptr<Teleoperation> tele_;
  TickInput input_;
};

}  // namespace needle::haptics
