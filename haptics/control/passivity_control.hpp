// Passivity at the device's port, guaranteed in the time domain: an observer of the energy the
// virtual world (controller, virtual robot, tissue) has dissipated, and a controller that acts on the
// tick to come while that energy would fall below zero (Hannaford and Ryu, "Time-domain passivity
// control of haptic interfaces", IEEE Trans. Robotics and Automation 18(1), 2002; its variable damper
// after Ryu, Kwon and Hannaford, "Stable teleoperation with time-domain passivity control", IEEE
// Trans. Robotics and Automation 20(2), 2004, which puts one at each port). docs/CONTROLLER.md,
// "Passivity guaranteed".
//
// The port is the device's actuators: the joint torque τ it was given and its joint motion q. Held
// over a tick (zero-order hold), the torque does exactly τ·Δq of work on the device, so
//   absorbed A(k) = −Σ τ(j−1)·(q(j) − q(j−1)), j ≤ k        (what the world took from the device),
//   dissipated D(k) = A(k) − (U(k) − U(0)),
// U the energy the world holds and may give back (Teleoperation::stored_energy). The world is
// passive at the port while D ≥ 0; the device's own mass between port and hand is passive, so then
// it is at the hand too.
//
// The controller acts on the tick's own flow, as Hannaford and Ryu's does (their observer counts the
// step's f(n)v(n)ΔT before the controller chooses its damping α(n)): if the device kept its velocity
// q̇ over the tick, the command τ would leave
//   D⁺ = D(k) − T τ·q̇ − (U⁺ − U(k)),   U⁺ the world's energy after its step with the device at q + T q̇
//   (to first order in T: Teleoperation::stored_energy_rate).
// While D⁺ < −D_owed it
//   withholds the share γ = min(1, −D⁺ / D_full) of the command's active part τ_a (all but the weight
//   compensation and the tool's weight, τ_c, whose energy is in U): a world that owes energy stops
//   pushing, whichever way the device moves within the tick;
//   damps the actuated joints for what is left, D⁺_γ = D⁺ + γ T τ_a·q̇:
//   τ −= β H_aa q̇_a, β = min(β_max, −D⁺_γ / (T q̇_aᵀH_aa q̇_a)), within what the device's force limit
//   leaves (room_within_limit).
// The device does not keep its velocity, and the damper is bounded: what the tick really leaves is the
// next tick's D, so a deficit not paid within one tick is carried and paid in the ticks after, as
// the PC carries its residual when its force is bounded. β T ≤ 1 keeps the damper stable on the
// device alone (each mode's velocity is at most brought to rest in a tick, never reversed); the
// hand's mass only adds to H. The virtual robot is damped the same way while the world owes
// energy (D < −D_owed): energy the world makes on its own side (the integration, the constraint's
// stabilisation) does not pass the port. Allocation-free.
#pragma once

#include "haptics/control/device_limit.hpp"
#include "haptics/model/types.hpp"

namespace needle::haptics {

struct PassivityGains {
  // β_max T: the largest share of the device's velocity the damper removes in one tick, in [0, 1];
  // 0 turns the observer and the damper off. Design value: 1, the most a damper held for one tick
  // can take without reversing the motion. Under the tool law only (ControlLaw::Tool); the thesis's
  // law runs as printed.
  double max_damping_per_tick = 1.0;
  // D_full: the predicted deficit at which the whole active part is withheld. Design value: half the
  // 1 mJ a bench row may owe, so the withholding is complete well before it.
  double full_at_J = 5e-4;
  // D_owed: the deficit from which the controller acts. Design value: 1 µJ, a thousandth of the 1 mJ
  // a bench row may owe, and far above the held torque's second-order remainder against U's
  // potentials (½ Δqᵀ∇²V Δq), which on the first ticks, where the weight compensation meets a device
  // at rest, measured 10⁻¹³ J at 2 ms ticks and 4·10⁻¹⁰ J at 16 ms: that remainder never switches the
  // controller on.
  double owed_from_J = 1e-6;
  bool enabled() const { return max_damping_per_tick > 0.0; }
};

// The observer's state, kept by the controller between ticks.
struct PassivityObserver {
  bool started = false;
  VecN q_prev;                         // the device's joints at the last tick
  VecN tau_prev;                       // the torque it was given for the tick since
  double absorbed_J = 0.0;             // A
  double stored0_J = 0.0;              // U(0)
  double stored_J = 0.0;               // U(k)
  double dissipated_J = 0.0;           // D(k)
  double predicted_J = 0.0;            // D⁺ of the last tick, before the controller acted
  double damping_per_s = 0.0;          // β of the last tick, 0 when the damper was off
  double virtual_damping_per_s = 0.0;  // β_v of the virtual robot's damper, 0 when off
  double share_withheld = 0.0;         // γ: the share of the command's active part withheld
};

// (q_m, U; observer) => (observer.absorbed_J, .stored_J, .dissipated_J)   one tick of the observer, with
// the torque the device was given since the last tick in observer.tau_prev (passivity_applied).
void observe_passivity(const VecN& q_m, double stored_J, PassivityObserver& obs);

// (τ, q̇_m, T, U⁺, observer) => D⁺ = D(k) − T τ·q̇_m − (U⁺ − U(k))   what the tick would leave if the device
// kept its velocity.
double predicted_dissipation(const VecN& tau_m, const VecN& dq_m, double T, double stored_next_J,
                             const PassivityObserver& obs);

// Whether a dissipated energy D (or D⁺) is a debt the controller acts on: D < −D_owed, the controller on.
inline bool passivity_owed(const PassivityGains& gains, double dissipated_J) {
  return gains.enabled() && dissipated_J < -gains.owed_from_J;
}

// (gains, limit, H_m, q̇_m, τ_c, T, observer.predicted_J = D⁺; τ_m within the limit) =>
// (τ_m ← τ_c + (1 − γ)(τ_m − τ_c) − β H_aa q̇_a; observer.share_withheld = γ, .damping_per_s = β)
// for a D⁺ the controller acts on (passivity_owed); τ_c the command's conservative part as the device's
// limit left it, H_m the device's inertia.
void passivity_control(const PassivityGains& gains, const DeviceLimit& limit, const MatN& H_m, const VecN& dq_m,
                       const VecN& tau_conservative, double T, PassivityObserver& obs, VecN& tau_m);

// (gains, H_v, q̇_v, T, observer; B_v) => (B_v += β_v diag(H_v); observer.virtual_damping_per_s = β_v),
// β_v = min(β_max, −D / (T q̇_vᵀ diag(H_v) q̇_v))   the virtual robot's damper, on only while D is owed: energy
// the world made on its own side (the virtual robot's integration, its constraint's stabilisation)
// never reaches the port, so the device's damper cannot remove it. B_v is the virtual world's
// implicit joint damping (VirtualWorld::advance), stable at any β_v.
void passivity_virtual_damping(const PassivityGains& gains, const MatN& H_v, const VecN& dq_v, double T,
                               PassivityObserver& obs, VecN& B_v);

// (τ given for the tick to come; observer) => (observer.tau_prev)   what the device was given after
// the safety monitor's saturation, which the observer must see, not the controller's command.
inline void passivity_applied(const VecN& tau_applied, PassivityObserver& obs) { obs.tau_prev = tau_applied; }

}  // namespace needle::haptics
