// What the hand feels, measured on a closed-loop run (`needle-sim bench feel`): per phase
// of contact, the sensed hand force's content in the band where a wobble is felt (3–50 Hz) and
// above it, the needle tip's lateral speed in tissue and the position tracking; and the force the
// hand holds at rest in free motion. Not for the servo loop.
#pragma once

#include <limits>
#include <vector>

#include "haptics/sim/closed_loop.hpp"

namespace needle::haptics {

enum class FeelPhase { Free, Rigid, Tissue };  // by the virtual tool's contact mode
const char* feel_phase_name(FeelPhase phase);

struct FeelWindows {
  double band_low_Hz = 3.0, band_high_Hz = 50.0;  // the band; "high frequency" is above band_high_Hz
  double tissue_settle_s = 0.3;                   // tissue ticks count from this long after each entry
  double lateral_settle_s = 1.0;                  // the lateral speed from this long after each entry
  double settle_out_s = 1.0;  // an entry is one after this long out of the tissue (not a flicker's re-entry)
};

struct PhaseFeel {
  FeelPhase phase = FeelPhase::Free;
  double seconds = 0.0;           // of ticks counted
  double force_band_rms_N = 0.0;  // RMS of |F_h| band-passed (zero-phase), over the phase's ticks
  double force_hf_rms_N = 0.0;    // RMS of |F_h| high-passed at band_high_Hz
  double max_lateral_speed_mps = std::numeric_limits<double>::quiet_NaN();  // tissue only: max |ψ|
  double tracking_rms_m = 0.0;                                              // RMS of |x_m − x_v|
};

// (ticks of one run, its period, windows) => one PhaseFeel per phase that has ticks, in the order
// free, rigid, tissue. The filters run over the whole run (so a phase's edges see its neighbours),
// forward and backward: second-order Butterworth sections, 3 Hz high-pass and 50 Hz low-pass for
// the band, 50 Hz high-pass above it (each applied twice: fourth order, no phase shift).
std::vector<PhaseFeel> feel_by_phase(const std::vector<TickRecord>& ticks, double period_s,
                                     const FeelWindows& windows = {});

// (signal, sample rate, corner, high or low) => the signal through a zero-phase second-order
// Butterworth filter run forward and backward, its ends padded with their own value for one second.
std::vector<double> zero_phase_filter(const std::vector<double>& x, double sample_Hz, double corner_Hz, bool high_pass);

// (scenario, hold) => mean |F_h| over the second half of a hold of the hand still at the script's
// first waypoint, where the scenario starts the robots at rest: what the hand carries in free motion.
double free_force_at_rest(Scenario scenario, double hold_s = 4.0);

}  // namespace needle::haptics
