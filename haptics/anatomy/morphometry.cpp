#include "haptics/anatomy/morphometry.hpp"

#include <algorithm>
#include <cmath>

// Sources (docs/PATIENTS.md lists them in full). "Re-read" marks the numbers read in the source's
// own table or abstract while writing this file; everything else is a design value, said so.
//
// [Cook2021]   Cook WH, Baker JF. Comparative analysis of lumbar spine vertebral morphology between
//              Māori and New Zealand Europeans: a computed tomography study. Int J Spine Surg
//              2021;15(6):1072-1081. Table 6 (L5, by sex) re-read; abstract re-read: the canal's
//              length is about constant through the lumbar spine, its width and the pedicles' width
//              grow to L5, the pedicles' height falls to L5.
// [Guj2012]    Calculation of canal/body ratio for lumbar spinal canal in dried vertebrae in Gujarat
//              (63 subjects, 2012), abstract re-read: interpedicular distance and body width at L1
//              and L5 by sex.
// [Singh2013]  Singh J, Pahuja K, Khatri JK. Morphometric analysis of the lumbar vertebrae in North
//              Indian population. Asian J Pharm Health Sci 2013;3(4):830-834, abstract re-read:
//              pedicle height 14.6 mm at L1 (greatest), 13.4 mm at L4 (least).
// [Vallejo2012] Vallejo MC, Fabio A, Phelps AL, et al. An epidural depth equation prior to
//              ultrasound visualization in obese parturients... SOAP 2012, abstract TW-5, re-read:
//              epidural depth (cm) = 6.63 - 0.07 height (in) + 0.02 weight (lb).
// [Bahk1998]   Bahk JH, Kim JH, Lee JS, Lee SC. Reg Anesth Pain Med 1998;23(3):262-265, abstract
//              re-read: skin to supraspinous ligament correlates with BMI and waist; supraspinous
//              ligament to epidural space correlates with no physical measurement.
// Panjabi et al. (Spine 1992) and Kunkel, Schmidt and Wilke (J Anat 2010) give every level and the
// posterior elements; their tables could not be read here, so the levels' ratios and the posterior
// elements below are design values until they are.

namespace needle::haptics::anatomy {
namespace {

constexpr double mm = 1e-3;

// Per level L1..L5: a value for each.
using PerLevel = std::array<double, kLumbarLevels>;

// Linear from the L1 value to the L5 value (design value: the sources give the two ends).
double l1_to_l5(double l1, double l5, int level) { return l1 + (l5 - l1) * level / 4.0; }

struct SexValues {
  double female, male;
  double of(Sex s) const { return s == Sex::Female ? female : male; }
};

// [Cook2021] Table 6, L5, mm (re-read).
constexpr SexValues kL5BodyPosteriorHeight{25.5, 26.8};
constexpr SexValues kL5BodyAnteriorHeight{29.6, 30.7};
constexpr SexValues kL5BodyDepth{33.3, 37.1};  // VBSL
constexpr SexValues kL5PedicleHeight{12.5, 13.1};
constexpr SexValues kL5PedicleWidth{15.1, 16.6};
constexpr SexValues kCanalLength{15.1, 15.9};  // VCL at L5, about constant through the lumbar spine
constexpr SexValues kL5CanalWidth{27.6, 28.5};
// [Cook2021] Table 6, the change with age at L5, mm a year (re-read), applied at every level from a
// reference age of 45 (design value: the cohort's mean age was not read).
constexpr double kBodyDepthPerYear = 0.084, kPedicleHeightPerYear = 0.011, kPedicleWidthPerYear = 0.033,
                 kCanalWidthPerYear = 0.033, kReferenceAge = 45.0;
// [Guj2012] mm (re-read): interpedicular distance and body width at L1 and L5.
constexpr SexValues kL1Interpedicular{21.3, 22.6}, kL5Interpedicular{26.4, 27.0};
constexpr SexValues kL1BodyWidth{31.6, 36.3}, kL5BodyWidth{42.8, 46.0};
// [Singh2013] pedicle height, mm (re-read at L1 and L4; L2 and L3 interpolated and L5 taken as L4's:
// design values, the height falling caudally as [Cook2021] says).
constexpr PerLevel kPedicleHeightShape{14.6, 14.3, 14.0, 13.4, 13.4};

// Design values, ratio to L5: posterior body heights within a few percent between levels, L5 the
// shortest (posterior wedging); anterior heights and depths growing to L5; pedicle width about
// doubling from L1 ([Singh2013]'s 7.1 mm minimum at L1) to L5 ([Cook2021]'s 16.1 mm).
constexpr PerLevel kBodyPosteriorHeightRatio{1.03, 1.06, 1.06, 1.05, 1.0};
constexpr PerLevel kBodyAnteriorHeightRatio{0.85, 0.90, 0.93, 0.97, 1.0};
constexpr PerLevel kBodyDepthRatio{0.86, 0.89, 0.93, 0.97, 1.0};
constexpr PerLevel kPedicleWidthRatio{0.55, 0.60, 0.70, 0.82, 1.0};

// Design values, mm, for the female reference stature (scaled like the rest): the posterior
// elements and discs of a textbook lumbar spine, chosen so that the spinous processes stand about 3
// cm behind the canal, the midline interlaminar windows open 7 to 13 mm upright (wider below), and
// the discs are wedged as the lordosis needs.
constexpr PerLevel kSpinousLength{30.0, 31.0, 31.0, 29.0, 25.0};
constexpr PerLevel kSpinousHeight{22.0, 24.0, 25.0, 24.0, 20.0};
constexpr double kSpinousThickness = 7.0, kLaminaThickness = 6.0;
constexpr PerLevel kTransverseSpan{70.0, 80.0, 90.0, 88.0, 85.0};
constexpr PerLevel kDiscPosterior{6.0, 6.5, 7.0, 7.5, 6.5}, kDiscAnterior{10.0, 11.0, 12.0, 13.0, 14.0};
constexpr PerLevel kInterlaminarGap{7.0, 9.0, 11.0, 12.0, 13.0};

// Design values: the reference statures the levels are scaled from, of adult women and men.
constexpr SexValues kReferenceStature{1.63, 1.77};

}  // namespace

double stature_scale(const PatientParams& p) { return p.height_m / kReferenceStature.of(p.sex); }

double epidural_depth_equation_m(const PatientParams& p) {
  const double height_in = p.height_m / 0.0254, weight_lb = p.weight_kg / 0.45359237;
  return (6.63 - 0.07 * height_in + 0.02 * weight_lb) * 0.01;  // [Vallejo2012]
}

VertebraDimensions vertebra_closed_form(const PatientParams& p, int level) {
  const double s = stature_scale(p), age = p.age_years - kReferenceAge;
  const size_t l = size_t(level);
  VertebraDimensions v;
  v.body_height_m = kL5BodyPosteriorHeight.of(p.sex) * kBodyPosteriorHeightRatio[l] * s * mm;
  v.body_anterior_height_m = kL5BodyAnteriorHeight.of(p.sex) * kBodyAnteriorHeightRatio[l] * s * mm;
  v.body_depth_m = (kL5BodyDepth.of(p.sex) * kBodyDepthRatio[l] * s + kBodyDepthPerYear * age) * mm;
  v.body_width_m = l1_to_l5(kL1BodyWidth.of(p.sex), kL5BodyWidth.of(p.sex), level) * s * mm;
  v.canal_depth_m = kCanalLength.of(p.sex) * s * mm;
  // [Cook2021]'s width at L5, the other levels in [Guj2012]'s proportion to it.
  const double interpedicular = l1_to_l5(kL1Interpedicular.of(p.sex), kL5Interpedicular.of(p.sex), level);
  v.canal_width_m =
      (kL5CanalWidth.of(p.sex) * interpedicular / kL5Interpedicular.of(p.sex) * s + kCanalWidthPerYear * age) * mm;
  v.pedicle_height_m =
      (kL5PedicleHeight.of(p.sex) * kPedicleHeightShape[l] / kPedicleHeightShape[4] * s + kPedicleHeightPerYear * age) *
      mm;
  v.pedicle_width_m = (kL5PedicleWidth.of(p.sex) * kPedicleWidthRatio[l] * s + kPedicleWidthPerYear * age) * mm;
  v.lamina_thickness_m = kLaminaThickness * s * mm;
  v.spinous_process_length_m = kSpinousLength[l] * s * mm;
  v.spinous_process_height_m = kSpinousHeight[l] * s * mm;
  v.spinous_process_thickness_m = kSpinousThickness * s * mm;
  v.transverse_process_span_m = kTransverseSpan[l] * s * mm;
  v.disc_posterior_height_m = kDiscPosterior[l] * s * mm;
  v.disc_anterior_height_m = kDiscAnterior[l] * s * mm;
  v.interlaminar_gap_neutral_m = kInterlaminarGap[l] * s * mm;
  return v;
}

PatientDimensions patient_dimensions(const PatientParams& p) {
  PatientRandom rng(p.seed);
  const auto vary = [&]() { return p.seed == 0 ? 0.0 : std::clamp(rng.normal(), -2.5, 2.5); };
  PatientDimensions d;
  for (int level = 0; level < kLumbarLevels; ++level) {
    VertebraDimensions v = vertebra_closed_form(p, level);
    for (double* x :
         {&v.body_height_m, &v.body_anterior_height_m, &v.body_depth_m, &v.body_width_m, &v.canal_depth_m,
          &v.canal_width_m, &v.pedicle_height_m, &v.pedicle_width_m, &v.lamina_thickness_m, &v.spinous_process_length_m,
          &v.spinous_process_height_m, &v.spinous_process_thickness_m, &v.transverse_process_span_m,
          &v.disc_posterior_height_m, &v.disc_anterior_height_m, &v.interlaminar_gap_neutral_m})
      *x *= 1.0 + 0.04 * vary();
    d.vertebrae[size_t(level)] = v;
  }
  const double s = stature_scale(p);
  // Design values: the skin of the back 3 mm thick (as the lumbar section's); the ligamentum flavum
  // 4 mm on the midline, the posterior epidural space 5 mm deep there, the dura 0.5 mm (as
  // assets/scenarios/lumbar_epidural.json's layers); the supraspinous ligament a 4 mm cord over the
  // spinous processes' tips.
  d.skin_thickness_m = 3.0 * mm;
  d.flavum_thickness_m = 4.0 * s * mm;
  d.posterior_epidural_depth_m = 5.0 * s * mm;
  d.dura_thickness_m = 0.5 * mm;
  d.supraspinous_radius_m = 4.0 * s * mm;
  // Design values: sitting flexed, each lumbar segment flexes 8° from upright, lying on the side with
  // the knees drawn up 5°, within a segment's flexion range of about ten degrees.
  d.segment_flexion_deg = p.posture == Posture::SittingFlexed ? 8.0 : 5.0;
  d.skin_to_epidural_l3_l4_m = epidural_depth_equation_m(p) + 4.0 * mm * vary();
  return d;
}

}  // namespace needle::haptics::anatomy
