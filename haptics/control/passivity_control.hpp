// Passivity at the device's port, guaranteed in the time domain: an observer of the energy the
// virtual world (controller, virtual robot, tissue) has dissipated, and a controller that acts only
// while that energy is negative (Hannaford and Ryu, "Time-domain passivity control of haptic
// interfaces", IEEE Trans. Robotics and Automation 18(1), 2002; its variable damper after Ryu, Kwon
// and Hannaford, "Stable teleoperation with time-domain passivity control", IEEE Trans. Robotics and
// Automation 20(2), 2004, which puts one at each port). docs/CONTROLLER.md, "Passivity guaranteed".
//
// The port is the device's actuators: the joint torque τ it was given and its joint motion q. Held
// over a tick (zero-order hold), the torque does exactly τ·Δq of work on the device, so
//   absorbed A(k) = −Σ τ(j−1)·(q(j) − q(j−1)), j ≤ k        (what the world took from the device),
//   dissipated D(k) = A(k) − (U(k) − U(0)),
// U the energy the world holds and may give back (Teleoperation::stored_energy). The world is
// passive at the port while D ≥ 0; the device's own mass between port and hand is passive, so then
// it is at the hand too. While D < 0 the controller
//   withholds the share γ = min(1, −D / D_full) of the command's active part (all but the weight
//   compensation and the tool's weight, τ_c, whose energy is in U): τ ← τ_c + (1 − γ)(τ − τ_c);
//   damps the device: τ −= β H_m q̇, β = min(β_max, −D / (T q̇ᵀH_mq̇)) (removes −D within a tick);
//   damps the virtual robot the same way (β_v on the diagonal of H_v, implicit in its integration),
//   since energy the world makes on its own side (the integration, the constraint's stabilisation)
//   does not pass the port.
// The damper alone (Hannaford and Ryu's form) cannot pay a deficit the world keeps making while the
// device saturates: the saturation scales the damper down with the rest (measured: a 16 ms tick in
// tissue gave the hand 0.26 J with or without it). Withholding the active part stops the world from
// pushing while it owes energy. β T ≤ 1 keeps the damper stable on the device alone (each mode's
// velocity is at most brought to rest in a tick, never reversed); the hand's mass only adds to H_m.
// Allocation-free.
#pragma once

#include "haptics/model/types.hpp"

namespace needle::haptics {

struct PassivityGains {
  // β_max T: the largest share of the device's velocity the damper removes in one tick, in [0, 1];
  // 0 turns the observer and the damper off. Design value: 1, the most a damper held for one tick
  // can take without reversing the motion. Under the tool law only (ControlLaw::Tool); the thesis's
  // law runs as printed.
  double max_damping_per_tick = 1.0;
  // D_full: the deficit at which the whole active part is withheld. Design value: half the 1 mJ a
  // bench row may owe (docs/CONTROLLER.md), so the withholding is complete well before it.
  double full_at_J = 5e-4;
  bool enabled() const { return max_damping_per_tick > 0.0; }
};

// The observer's state, kept by the controller between ticks.
struct PassivityObserver {
  bool started = false;
  VecN q_prev;               // the device's joints at the last tick
  VecN tau_prev;             // the torque it was given for the tick since
  double absorbed_J = 0.0;   // A
  double stored0_J = 0.0;    // U(0)
  double dissipated_J = 0.0; // D
  double damping_per_s = 0.0;  // β of the last tick, 0 when the damper was off
  double virtual_damping_per_s = 0.0;  // β_v of the virtual robot's damper, 0 when off
  double share_withheld = 0.0;         // γ: the share of the command's active part withheld
};

// (q_m, U; observer) => (observer.absorbed_J, .dissipated_J)   one tick of the observer, with the
// torque the device was given since the last tick in observer.tau_prev (passivity_applied).
void observe_passivity(const VecN& q_m, double stored_J, PassivityObserver& obs);

// (gains, H_m, q̇_m, τ_c, T, observer; τ_m) => (τ_m ← τ_c + (1 − γ)(τ_m − τ_c) − β H_m q̇_m;
// observer.share_withheld = γ, .damping_per_s = β)   on only while observer.dissipated_J < 0.
void passivity_control(const PassivityGains& gains, const MatN& H_m, const VecN& dq_m, const VecN& tau_conservative,
                       double T, PassivityObserver& obs, VecN& tau_m);

// (gains, H_v, q̇_v, T, observer; B_v) => (B_v += β_v diag(H_v); observer.virtual_damping_per_s = β_v),
// β_v = min(β_max, −D / (T q̇_vᵀ diag(H_v) q̇_v))   the virtual robot's damper, on only while D < 0: energy
// the world made on its own side (the virtual robot's integration, its constraint's stabilisation)
// never reaches the port, so the device's damper cannot remove it. B_v is the virtual world's
// implicit joint damping (VirtualWorld::advance), stable at any β_v.
void passivity_virtual_damping(const PassivityGains& gains, const MatN& H_v, const VecN& dq_v, double T,
                               PassivityObserver& obs, VecN& B_v);

// (τ given for the tick to come; observer) => (observer.tau_prev)   what the device was given after
// the safety monitor's saturation, which the observer must see, not the controller's command.
inline void passivity_applied(const VecN& tau_applied, PassivityObserver& obs) { obs.tau_prev = tau_applied; }

}  // namespace needle::haptics
