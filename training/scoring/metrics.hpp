// The scoring metrics of one step or of a whole session (formulas and units in docs/SCORING.md).
// NaN marks a metric that does not apply (no target in the step, no held force, too few samples).
#pragma once

#include <cstdint>
#include <limits>

namespace needle::training {

inline constexpr double kNotApplicable = std::numeric_limits<double>::quiet_NaN();

struct Metrics {
  double duration_s = 0.0;
  double tissue_time_s = 0.0;                  // time the needle was in tissue
  double tip_error_m = kNotApplicable;         // tip to the target marker at the end
  double axis_deviation_deg = kNotApplicable;  // needle axis to the planned axis
  double lateral_load_Ns = 0.0;                // integral of |lateral multipliers| in tissue
  double lateral_peak_N = 0.0;                 // peak |lateral multipliers| in tissue
  double peak_force_N = 0.0;                   // peak |rigid contact force| (F_v: bone or the rigid surface), scene N
  double peak_axial_force_N = 0.0;             // peak |tissue's force along the needle|, scene N
  double peak_needle_force_N = 0.0;            // peak |world's force on the needle| (needle_force.hpp), scene N
  double peak_hand_force_N = 0.0;              // peak of it at the hand, force scale times, N: the scored peak
  double force_limited_s = 0.0;                // time the device held the force back at its limit
  double passivity_damped_s = 0.0;             // time the passivity controller acted (the world owed energy)
  double force_sd_N = kNotApplicable;          // steadiness while holding a force
  double path_length_m = 0.0;                  // tip path
  double ideal_path_m = 0.0;                   // straight line, start to end
  double normalized_jerk = kNotApplicable;     // dimensionless, sqrt(T^5 / (2 L^2) * integral |jerk|^2)
  double needle_visibility =
      kNotApplicable;           // share of the inserted needle in the ultrasound slice, time mean in tissue
  uint32_t withdrawals = 0;     // tissue -> free
  uint32_t reinsertions = 0;    // free -> tissue after a first insertion
  uint32_t rigid_contacts = 0;  // entries into a rigid surface the step did not ask for
  uint32_t faults = 0;          // safety faults latched
  uint32_t first_fault = 0;     // haptics::FaultCause of the first, 0 when none
  // Layered tissue (zero or not applicable without it).
  uint32_t punctures = 0;               // membranes punctured (layers with a puncture force passed into)
  double overshoot_m = kNotApplicable;  // the tip's travel along the needle after the last puncture until it stopped
  uint32_t bone_contacts = 0;           // the tip meeting a rigid layer (bone), chatter within 0.25 s one contact
  double bone_peak_force_N = 0.0;       // peak |force of the tool on bone|
  uint32_t redirections = 0;            // withdrawals to a shallower layer followed by a re-advance deeper
  uint32_t forbidden_punctures = 0;     // layers the step forbids punctured (the dura)
  // A generated patient (docs/SCORING.md, "Patients"; the session's, not applicable without one or
  // until the event happens; reported, not scored).
  double interspace_entered = kNotApplicable;  // 1 (L1-L2) to 5 (L5-S1): where the needle first entered the skin
  double entry_angle_deg = kNotApplicable;     // the needle to that interspace's midline approach as it entered
  double lor_depth_m = kNotApplicable;  // from the skin along the needle when the tip first reached the epidural space
  double lor_depth_error_m = kNotApplicable;  // that less the patient's own skin-to-epidural distance there
  // The loss-of-resistance syringe (training/scoring/syringe_events.hpp; not applicable without one).
  double advance_after_loss_m =
      kNotApplicable;  // the tip's furthest advance along the needle after the loss in the syringe's space
  double loss_pressure_before_Pa = kNotApplicable;  // the barrel's pressure while the plunger was held before that loss
  double loss_pressure_after_Pa = kNotApplicable;   // and kLossSettle_s after it
  double false_losses = kNotApplicable;             // losses of resistance outside the syringe's space (fat): a count
  double pressure_applied_s = kNotApplicable;       // time the thumb pressed the plunger
};

}  // namespace needle::training
