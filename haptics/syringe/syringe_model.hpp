// The loss-of-resistance syringe on the needle's hub, as data: its fluid (saline or air), its
// plunger, its fill and the needle's lumen the fluid leaves through, and the thumb pressing the
// plunger. Immutable; the per-tick state is SyringeState (haptics/syringe/syringe_step.hpp). The
// tissue at the tip decides where the fluid may go (LayerInjection, haptics/tissue/tissue_model.hpp).
// Equations and sources: docs/TISSUE.md, "The syringe".
#pragma once

#include <cstdint>
#include <optional>

#include "haptics/tissue/tissue_model.hpp"

namespace needle::haptics {

enum class SyringeFluid : uint32_t { kSaline = 1, kAir = 2 };

// "saline", "air"; parse_syringe_fluid is its inverse (nullopt for anything else).
const char* syringe_fluid_name(SyringeFluid fluid);
std::optional<SyringeFluid> parse_syringe_fluid(const char* name);

// Standard atmosphere (ISO 2533): the air in the syringe starts at it; pressures are gauge.
inline constexpr double kAmbientPressure_Pa = 101325.0;
// Dynamic viscosities at 20 °C (CRC Handbook of Chemistry and Physics, "Viscosity of liquids" and
// "of gases"): water 1.002 mPa·s, taken for 0.9 % saline (about 2 % above water's); dry air
// 18.1 µPa·s.
inline constexpr double kSalineViscosity_Pa_s = 1.002e-3;
inline constexpr double kAirViscosity_Pa_s = 1.81e-5;
double fluid_viscosity_Pa_s(SyringeFluid fluid);

struct SyringeParams {
  SyringeFluid fluid = SyringeFluid::kSaline;
  // 1.77 cm² (a 15.0 mm plunger): the ratio of force to pressure Vaughan et al. (2012) measured
  // on their loss-of-resistance syringe, 11.1 N at 470 mmHg and 11.8 N at 500 mmHg, both 1.77 cm².
  double plunger_area_m2 = 1.77e-4;
  // Design value: 5 mL, the fill a loss-of-resistance syringe (5 to 10 mL) is used with; the
  // plunger's stroke is fill / area, 28 mm.
  double fill_volume_m3 = 5e-6;
  // Design value: an 18 G thin-walled Tuohy needle of 90 mm, its bore about 0.9 mm.
  double lumen_radius_m = 4.5e-4;
  double lumen_length_m = 0.09;
  // Design value: the operator model's hand damping (van Beek et al. 2015, 6.45 N·s/m, the arm's;
  // haptics/sim/operator_model.hpp), taken for the thumb pressing the plunger with the hand behind
  // it: the thumb's force on the plunger falls by b·v while the plunger runs away from it. No
  // measurement of a thumb's damping was found in the sources searched.
  double thumb_damping_Ns_per_m = 6.45;
};

// The numbers of SyringeParams by their keys in scenario and task files, each in (0, max], with
// reasons in docs/TISSUE.md ("The syringe", ranges): past them a number is a typo, not a syringe.
inline constexpr ParameterField<SyringeParams> kSyringeFields[] = {
    {"plunger_area_m2", &SyringeParams::plunger_area_m2, 1e-3, "m^2"},
    {"fill_volume_m3", &SyringeParams::fill_volume_m3, 6e-5, "m^3"},
    {"lumen_radius_m", &SyringeParams::lumen_radius_m, 2e-3, "m"},
    {"lumen_length_m", &SyringeParams::lumen_length_m, 0.3, "m"},
    {"thumb_damping_Ns_per_m", &SyringeParams::thumb_damping_Ns_per_m, 1000.0, "N*s/m"}};

// The parameter at fault and why, or nothing when every number is in (0, max].
std::optional<MechanicsProblem> syringe_problem(const SyringeParams& p);

// The plunger's stroke: the fill over the plunger's area, m.
double syringe_stroke_m(const SyringeParams& p);

// Hagen–Poiseuille: the lumen's resistance to the syringe's fluid, R = 8 μ L / (π r⁴), Pa·s/m³.
double lumen_resistance_Pa_s_per_m3(const SyringeParams& p);

// The flow path from the barrel through the lumen into the tissue at the tip: the tissue's opening
// pressure, and the lumen's and the tissue's resistances in series, the tissue's (given for saline)
// scaled to the syringe's fluid by the viscosities (Darcy's law: a porous medium's resistance is
// proportional to the fluid's viscosity). Outside the tissue (tip = nullptr) the tip is open.
struct FlowPath {
  double opening_pressure_Pa = 0.0;
  double resistance_Pa_s_per_m3 = 0.0;
};
FlowPath flow_path(const SyringeParams& p, const LayerInjection* tip);

}  // namespace needle::haptics
