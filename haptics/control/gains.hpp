// Gains of the teleoperation controller (thesis 3.2), per robot and per constraint, with the
// values of the thesis's experiments as named defaults.
#pragma once

#include <optional>
#include <string>
#include <string_view>

#include "haptics/constraints/nonholonomic_multiplier.hpp"
#include "haptics/constraints/penalty_contact.hpp"
#include "haptics/control/passivity_control.hpp"
#include "haptics/model/types.hpp"

namespace needle::haptics {

// Diagonal gains of one robot's law; Kf is a scalar gain on the force (momentum) error.
struct RobotGains {
  VecN Ka, Kp, Lambda, Kbeta, Kgamma;
  double Kf = 0.0;
};

// How the velocity feedback of the virtual robot's laws (3.14), (3.21), (3.28) is signed.
// AsPrinted reproduces the thesis's "+K_av q̇_v + K_pv s_av", which feeds velocity back
// positively; kept only to show (tests, bench stability) that it is the form that diverges.
enum class VirtualFeedback { Dissipative, AsPrinted };

// Which controller runs (docs/CONTROLLER.md, "The laws"). Thesis: the thesis's laws as printed
// (signs corrected, the blend and the wrench filter added, nothing else): the
// master's gravity cancelled only in contact, the virtual robot's weight carried by its tracking
// terms, the tissue entered while the tip is inside its surface. A recording that names no law was
// made with it. Tool: what the hand holds is the tool: both robots' gravity compensated in every
// mode, the tool's weight rendered, the sensed wrench taken net of it, entry into tissue one event
// of the needle's track, and the tissue's axial force fed back to the hand.
enum class ControlLaw { Thesis, Tool };
const char* control_law_name(ControlLaw law);
std::optional<ControlLaw> control_law_named(std::string_view name);

// The instrument the trainee holds. Default: an 18 G needle on a 5 ml syringe, 15 g
// (design value: a 5 ml plastic syringe weighs about 10 g, the needle and its hub 1 to 2 g, a few
// millilitres of saline or air the rest). Its weight is what the hand carries in free motion.
struct Tool {
  std::string name = "needle with syringe";
  double mass_kg = 0.015;
};

struct TeleoperationGains {
  RobotGains master, virt;
  GpmParams gpm;
  NonholonomicGains nonholonomic;
  double switch_time_s = 0.02;  // contact terms blend in and out over this time
  // First-order low-pass on the sensed wrench before it enters the force terms. Without it the
  // hand's inertial force, measured by the sensor and reflected one tick late, cancels the hand's
  // mass and the master limit-cycles in tissue (see docs/CONTROLLER.md). Not in the thesis.
  double force_filter_Hz = 15.0;
  VirtualFeedback virtual_feedback = VirtualFeedback::Dissipative;
  ControlLaw law = ControlLaw::Tool;
  Tool tool;  // used by ControlLaw::Tool
  // Newtons at the hand per newton in the scene, for every force term: the hand feels s F_scene,
  // its push enters the scene as F_h / s. Below 1 for tissue whose forces exceed the device's
  // (docs/CONTROLLER.md, "Force scale"). 1 keeps the thesis's laws as they are.
  double force_scale = 1.0;
  // ControlLaw::Tool: damping of the master tip's motion across the needle while it is in tissue,
  // N·s/m at the hand (docs/CONTROLLER.md, "No wobble"). Design value: at 10 N·s/m the 6 Hz ring
  // of the lateral force reflection is gone (band 3-50 Hz of F_h 0.038 -> 0.009 N rms in the thesis's
  // insertion) while the hand moves sideways at most millimetres a second in tissue (0.01 N felt).
  double lateral_damping_Ns_per_m = 10.0;
  // ControlLaw::Tool: stiffness of the spring holding the master tip to the virtual needle's line
  // while it is in tissue, N/m at the hand; above 0 it and the lateral damper replace (3.27)'s
  // reflected multipliers at the master (docs/CONTROLLER.md, "Passivity at the hand"). 0 (the
  // default): the reflection. The layered scenarios set 300 N/m (design value): with the reflection
  // the master drifted up to 7 cm across a needle the tissue held and the world did net work on the
  // hand (-0.22 J in liver_biopsy); with the spring none does and tracking in tissue is under 1 mm
  // RMS; a 1 cm push across the needle is felt as 3 N (the Omni's peak); its sample-and-hold activity
  // K T / 2 = 0.3 N·s/m at T = 2 ms is a twentieth of the hand's damping (6.45 N·s/m). Not the default
  // yet: in the thesis's penetrable-sphere task it threw the virtual needle 5 cm out of the sphere at
  // withdrawal (the sliding integral σ wound up while the constraint held the needle).
  double lateral_stiffness_N_per_m = 0.0;
  // ControlLaw::Tool: damping of the master tip's motion along the needle while the tissue's axial
  // force acts (layers with friction, cutting or a surface), N·s/m at the hand (docs/CONTROLLER.md,
  // "The tissue along the needle"). Design value: the axial loop (hand push -> virtual needle ->
  // friction -> hand) limit-cycled at about 6 Hz with ±1.2 N when withdrawing through muscle; band
  // 3-50 Hz of F_h in tissue_block_layers 0.34 N at 0, 0.24 at 15, 0.08 at 20, 0.015 at 30 N·s/m.
  // An insertion at 5 mm/s feels 0.15 N of it.
  double axial_damping_Ns_per_m = 30.0;
  // ControlLaw::Tool: stiffness of the spring along the needle between the master tip and the virtual
  // tip while the tissue's axial force acts, scene N/m; above 0 it replaces the force-force axial
  // channel (the hand's push driving the virtual needle, the tissue's force reflected): the virtual
  // needle is pulled along its axis by K x₅ᵀ(x_m − x_v), the master held back by s K x₅ᵀ(x_m − x_v)
  // (docs/CONTROLLER.md, "The needle along the hand"). 0 (the default): the force-force channel, under
  // which the virtual needle ran ahead of the hand by the tissue's stored force when a membrane gave
  // way (10 mm through the epidural space and the dura in 50 ms). The epidural scenario sets it.
  double axial_stiffness_N_per_m = 0.0;
  // ControlLaw::Tool: the passivity observer and its damper at the device's port
  // (haptics/control/passivity_control.hpp; docs/CONTROLLER.md, "Passivity guaranteed").
  PassivityGains passivity;
};

// Section 4.3 (holonomic experiment, law (3.20)-(3.21)) and 4.4 (nonholonomic, (3.27)-(3.28)),
// for n joints; the printed K_pv = diag(0.2, 0.2, 0.2, 0.1, 0.1) is extended with 0.1 past joint 5.
TeleoperationGains thesis_holonomic_gains(int n);
TeleoperationGains thesis_nonholonomic_gains(int n);

}  // namespace needle::haptics
