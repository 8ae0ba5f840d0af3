// The generated patient's dimensions in closed form: each vertebra's from the morphometry the
// sources give (per sex, at L5), the other levels by ratios, scaled with stature and age; the
// depth of the epidural space from the skin from a clinical prediction equation in height and
// weight. Every number's source (or "design value" and why) is beside it in morphometry.cpp and in
// docs/PATIENTS.md.
#pragma once

#include <array>
#include <string>

#include "haptics/anatomy/patient_params.hpp"

namespace needle::haptics::anatomy {

// L1 to L5, then the sacrum's first segment.
inline constexpr int kLumbarLevels = 5;
inline constexpr std::array<const char*, 6> kLevelNames{"L1", "L2", "L3", "L4", "L5", "S1"};
// The interspaces below each lumbar level: "L1-L2" ... "L5-S1".
inline constexpr std::array<const char*, 5> kInterspaceNames{"L1-L2", "L2-L3", "L3-L4", "L4-L5", "L5-S1"};

// One lumbar vertebra (metres) and the disc and interspace below it.
struct VertebraDimensions {
  double body_height_m = 0.0;           // posterior height of the body (VBPH)
  double body_anterior_height_m = 0.0;  // VBAH
  double body_depth_m = 0.0;            // antero-posterior length of the endplate (VBSL)
  double body_width_m = 0.0;            // transverse
  double canal_depth_m = 0.0;           // antero-posterior length of the canal (VCL)
  double canal_width_m = 0.0;           // transverse (VCW, the interpedicular distance)
  double pedicle_height_m = 0.0;        // PH
  double pedicle_width_m = 0.0;         // PW
  double lamina_thickness_m = 0.0;
  double spinous_process_length_m = 0.0;  // from the canal's posterior border to the tip
  double spinous_process_height_m = 0.0;  // cranio-caudal, at the tip
  double spinous_process_thickness_m = 0.0;
  double transverse_process_span_m = 0.0;  // tip to tip
  double disc_posterior_height_m = 0.0;    // the disc below
  double disc_anterior_height_m = 0.0;
  double interlaminar_gap_neutral_m = 0.0;  // on the midline, below this level, the spine upright
};

struct PatientDimensions {
  std::array<VertebraDimensions, kLumbarLevels> vertebrae;
  double skin_thickness_m = 0.0;
  double skin_to_epidural_l3_l4_m = 0.0;  // on the midline, the needle's path (the prediction equation)
  double segment_flexion_deg = 0.0;       // each lumbar segment's flexion from the upright posture
  double flavum_thickness_m = 0.0;
  double posterior_epidural_depth_m = 0.0;  // flavum to dura on the midline
  double dura_thickness_m = 0.0;
  double supraspinous_radius_m = 0.0;
};

// (patient) => the dimensions. For seed 0 exactly the closed forms below; otherwise each
// dimension multiplied by its own draw of 1 + 0.04·z (z standard normal, clipped to ±2.5) and the
// depth to the epidural space shifted by 4 mm·z (design values: a few percent between people of
// one stature, and about the equation's residual).
PatientDimensions patient_dimensions(const PatientParams& p);

// The closed forms, without variation, each a function of the patient (tests compare to them).
// Stature scale: height over the reference stature of the patient's sex.
double stature_scale(const PatientParams& p);
// Vallejo et al.'s epidural depth equation (cm = 6.63 − 0.07 height(in) + 0.02 weight(lb)), in m.
double epidural_depth_equation_m(const PatientParams& p);
// A lumbar vertebra's dimensions at `level` (0 = L1 ... 4 = L5) without variation.
VertebraDimensions vertebra_closed_form(const PatientParams& p, int level);

}  // namespace needle::haptics::anatomy
