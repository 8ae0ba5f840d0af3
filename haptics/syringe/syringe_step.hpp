// The loss-of-resistance syringe, one servo tick at a time: the thumb's force on the plunger and
// the tissue at the needle's tip give the plunger's travel, the barrel's pressure and the flow into
// the tissue. Allocation-free, no locks, no I/O: it runs in the servo tick. Equations and their
// closed forms: docs/TISSUE.md, "The syringe".
//
// The plunger is massless; the thumb is a force F with the damping b of the hand behind it, so the
// plunger is pushed with F − b v. Pressures are gauge (above the atmosphere p₀).
//   Saline (incompressible): the plunger moves only as fast as the fluid leaves through the lumen
//   and into the tissue, Q = A v = (p − p_o)/R above the tissue's opening pressure p_o, none below:
//     v = max(0, F − A p_o) / (b + A² R),   p = (F − b v)/A.
//   Air (isothermal, Boyle): the gas's content m = (p₀ + p) V_g is kept while the plunger compresses
//   it, V_g = V_fill + V_dead − A x, and leaves through the same path at the air's viscosity,
//   dm = −(p₀ + p) Q dt.
#pragma once

#include "haptics/syringe/syringe_model.hpp"

namespace needle::haptics {

// Design value: the Luer nozzle and the needle's hub, about 0.1 mL, hold fluid the plunger cannot
// expel; for air it keeps the gas's volume above zero when the plunger reaches the barrel's end.
inline constexpr double kSyringeDeadVolume_m3 = 1e-7;

struct SyringeState {
  double travel_m = 0.0;         // plunger from the full position, ≤ the stroke
  double gas_J = 0.0;            // air: (p₀ + p) V_g, the gas's content (∝ its moles); 0 for saline
  double injected_m3 = 0.0;      // fluid gone into the tissue (air: at the atmosphere's pressure)
  double pressure_Pa = 0.0;      // in the barrel, gauge, at the end of the tick
  double flow_m3_per_s = 0.0;    // out of the barrel into the lumen in the tick
  double thumb_force_N = 0.0;    // what the thumb pressed with (≥ 0)
  double plunger_force_N = 0.0;  // what the fluid pushed back on the plunger, A times its pressure
  double work_J = 0.0;           // Σ plunger force × travel: the work the thumb did on the syringe
};

// (params) => the syringe full, at rest, the air (if any) at the atmosphere's pressure.
SyringeState syringe_at_rest(const SyringeParams& params);

// (params, state, F, the flow path at the tip, dt > 0) => (state)
//   F < 0 or NaN is taken as 0: a thumb only pushes. The plunger stops at the barrel's end (the
//   stroke) and at its full position. Air: the compression is solved implicitly with the force
//   balance (a quadratic in v), then the leak implicitly in the pressure (a quadratic in p₀ + p),
//   so the tick is unconditionally stable and never gives back more energy than the gas stored.
void step_syringe(const SyringeParams& params, SyringeState& state, double thumb_force_N, const FlowPath& path,
                  double dt);

// (params, state) => the energy the compressed air holds and can give back, relative to the
// atmosphere: E = m ln(m / (p₀ V_g)) − m + p₀ V_g ≥ 0 (0 for saline). work_J − E is what the syringe
// has dissipated (≥ 0: docs/TISSUE.md, "The syringe", passivity).
double syringe_stored_energy(const SyringeParams& params, const SyringeState& state);

}  // namespace needle::haptics
