// Gains of the teleoperation controller (thesis 3.2), per robot and per constraint, with the
// values of the thesis's experiments as named defaults.
#pragma once

#include "haptics/constraints/nonholonomic_multiplier.hpp"
#include "haptics/constraints/penalty_contact.hpp"
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
};

// Section 4.3 (holonomic experiment, law (3.20)-(3.21)) and 4.4 (nonholonomic, (3.27)-(3.28)),
// for n joints; the printed K_pv = diag(0.2, 0.2, 0.2, 0.1, 0.1) is extended with 0.1 past joint 5.
TeleoperationGains thesis_holonomic_gains(int n);
TeleoperationGains thesis_nonholonomic_gains(int n);

}  // namespace needle::haptics
