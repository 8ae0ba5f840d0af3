// The losses of resistance in a syringe's run, tick by tick: the moments the fluid starts to leave
// the barrel into the tissue under the thumb after it could not (a residue of pressure bleeding out
// with the thumb off the plunger is no loss). Read by the insertion bench and by the scoring
// from the syringe's per-tick state; allocation-free.
#pragma once

namespace needle::haptics {

// Design value: a flow of 0.05 mL/s (the plunger creeping 0.3 mm/s) starts a loss. Below every
// flow the shipped tissues let through under a thumb pressing enough to move the plunger at all
// (the fat's false loss under 11 N, 0.4 mL/s; docs/TISSUE.md), and above the rounding of a still one.
inline constexpr double kLossFlow_m3_per_s = 5e-8;
// Design value: the pressure after the loss is read 50 ms after it began: the air's leak through
// the needle settles within a few milliseconds, and a trainee's reaction (about 0.2 s) comes later.
inline constexpr double kLossSettle_s = 0.05;

struct LossOfResistance {
  double t_s = 0.0;  // the first tick of the flow
  int layer = -1;    // the layer holding the tip then, −1 in none
  double pressure_before_Pa =
      0.0;  // the largest barrel pressure while the plunger was held (since the flow last stopped)
  double pressure_after_Pa = 0.0;  // kLossSettle_s later (or at the run's end, if sooner)
  bool settled = false;            // pressure_after_Pa has been read
};

class LossDetector {
 public:
  // One tick's time, flow, barrel pressure, tip layer and thumb force, in time order. Returns true
  // when a loss begins in this tick; the loss is then current() and its pressure after is read
  // kLossSettle_s later.
  bool add(double t_s, double flow_m3_per_s, double pressure_Pa, int layer, double thumb_force_N);
  // The last loss begun (valid once add() has returned true once).
  const LossOfResistance& current() const { return current_; }
  // Whether the last loss's pressure after has just been read in the last add().
  bool settled_now() const { return settled_now_; }

 private:
  bool flowing_ = false;
  bool any_ = false;
  bool settled_now_ = false;
  double held_peak_Pa_ = 0.0;
  LossOfResistance current_;
};

}  // namespace needle::haptics
