// The range of every number a scenario file (assets/scenarios/*.json) and an operator script's
// `hand` may hold, checked on reading (haptics/sim/scenario.cpp): a number outside is
// "FILE: /pointer: must be in RANGE, got VALUE". Each is a design value: wide enough for any
// tuning the docs describe, narrow enough that a value past it can only be a typo or an attack
// (a stiffness of 1e300 N/m is not a tissue), never a run that hangs or ends in NaN. The reasons,
// and the table, are in docs/HAPTICS.md ("Scenario files: ranges"). Positions and times take the
// shared ranges of io/input_limits.hpp; a layer's mechanics, the ranges of their key table
// (haptics/tissue/tissue_model.hpp).
#pragma once

#include "io/input_limits.hpp"

namespace needle::haptics::limits {

using io::Range;

// The haptic loop's rates, 250 to 10000 Hz (kMinLoopRateHz, kMaxLoopRateHz of
// haptics/realtime/haptic_loop.hpp, which checks that they agree): a task runs its scenario at 1 / period_s.
inline constexpr Range kPeriod{1e-4, 4e-3, false, "s"};
// Sub-steps of a servo period: the thesis's scenarios take 8 (master) and 1 to 4 (virtual); 100
// makes a 20 us step at 2 ms, finer than the stiffest contact in the files needs. The work of a
// run grows with them (1000000 would take hours a simulated second).
inline constexpr int kMaxSubsteps = 100;
// An initial joint angle: one turn either way (a revolute joint past it is at a pose within it).
inline constexpr Range kJointAngle{-6.283185307179586, 6.283185307179586, false, "rad"};

// Gains (thesis section 4.3 and 4.4 values in brackets): the GPM's virtual mass [0.02 kg],
// damping ratio [100] and natural frequency [200 rad/s], the nonholonomic multiplier's α [50 1/s]
// and β [2500 1/s², = α²]: up to 100 times the thesis's value (β: 100², keeping β = α² reachable).
inline constexpr Range kGpmAlpha{0.0, 2.0, true, "kg"};
inline constexpr Range kGpmXi{0.0, 1e4, true, ""};
inline constexpr Range kGpmOmega{0.0, 2e4, true, "rad/s"};
inline constexpr Range kNonholonomicAlpha{0.0, 5e3, true, "1/s"};
inline constexpr Range kNonholonomicBeta{0.0, 2.5e7, true, "1/s^2"};
// The contact terms' blend [0.02 s]: past a second it is no longer a contact's onset.
inline constexpr Range kSwitchTime{0.0, 1.0, true, "s"};
// Hand newtons per scene newton [1; 0.25 in the epidural]: the scenes' forces reach 10 N and a
// desk device renders 3 to 9 N, so a scale past 10 only saturates the device.
inline constexpr Range kForceScale{0.0, 10.0, true, ""};
// The tool law's dampers [10 and 30 N·s/m] and springs [300 and 3000 N/m]: 500 N·s/m is 80 times
// the hand's own damping (6.45 N·s/m) and 1e5 N/m (100 N/mm) a hundred times the stiffest desk
// device (the Omni's 1.02 N/mm).
inline constexpr Range kToolDamping{0.0, 500.0, false, "N*s/m"};
inline constexpr Range kToolStiffness{0.0, 1e5, false, "N/m"};
// The passivity controller's damper [1]: the share of the device's velocity it may remove in a tick;
// past 1 it would reverse the motion (haptics/control/passivity_control.hpp). 0 turns it off.
inline constexpr Range kPassivityDampingPerTick{0.0, 1.0, false, ""};
// The instrument's mass [15 g]: a needle on a syringe weighs grams; 1 kg is past any instrument
// held like a pen (the Omni's 3.3 N carries 0.34 kg).
inline constexpr Range kToolMass{0.0, 1.0, false, "kg"};

// Sizes of surfaces and layers: a sphere's or a capsule's radius, a slab's thickness. A body part
// is under a metre across; 1 um is below what the layers resolve (docs/TASKS.md, "Layers").
inline constexpr Range kShapeSize{1e-6, 1.0, false, "m"};

// The hand [van Beek et al. 2015: 0.554 kg, 6.45 N·s/m, 135 N/m; grip 5 cm, design value]: a
// mass up to 10 kg (a whole arm, upper arm, forearm and hand, is 5% of body mass, 3.5 kg at
// 70 kg: Winter, Biomechanics and Motor Control of Human Movement, anthropometric data); damping up to 200 N·s/m and
// stiffness up to 5000 N/m (30 times the identified values; the epidural's stiff grip is 600 N/m); a grip up to 20 cm
// (a hand's span).
inline constexpr Range kHandMass{0.0, 10.0, true, "kg"};
inline constexpr Range kHandDamping{0.0, 200.0, false, "N*s/m"};
inline constexpr Range kHandStiffness{0.0, 5000.0, false, "N/m"};
inline constexpr Range kGripLength{0.0, 0.2, true, "m"};

// The force sensor [bias 0.02 N, noise 1/320 N, 500 Hz]: a bias or a noise past 10 N is larger
// than every force a task has; a bandwidth up to the loop's fastest rate (10 kHz).
inline constexpr Range kSensorBias{-10.0, 10.0, false, "N"};
inline constexpr Range kSensorNoise{0.0, 10.0, false, "N"};
inline constexpr Range kSensorBandwidth{0.0, 1e4, true, "Hz"};
// The device's force limit [3.3 N, the Omni]: a Falcon renders 9 N; 100 N is past any desk device.
inline constexpr Range kDeviceForceLimit{0.0, 100.0, true, "N"};
// The run's energy bound [5 J]: the mechanical energy of a hand, a desk device and a needle is
// under a joule; 100 J would let any instability run its course unseen.
inline constexpr Range kEnergyBound{0.0, 100.0, true, "J"};

// The tissue's stick [5000 N/m, 0.5 mm/s]: a grip stiffer than 1e6 N/m (1 N/um) or a band faster
// than 0.1 m/s (a needle's insertion speed is millimetres a second) is not sticking.
inline constexpr Range kStickStiffness{0.0, 1e6, true, "N/m"};
inline constexpr Range kStickBand{0.0, 0.1, true, "m/s"};

}  // namespace needle::haptics::limits
