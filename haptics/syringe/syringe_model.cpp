#include "haptics/syringe/syringe_model.hpp"

#include <cmath>
#include <cstdio>
#include <cstring>
#include <numbers>

namespace needle::haptics {

const char* syringe_fluid_name(SyringeFluid fluid) { return fluid == SyringeFluid::kAir ? "air" : "saline"; }

std::optional<SyringeFluid> parse_syringe_fluid(const char* name) {
  for (const SyringeFluid f : {SyringeFluid::kSaline, SyringeFluid::kAir})
    if (std::strcmp(name, syringe_fluid_name(f)) == 0) return f;
  return std::nullopt;
}

double fluid_viscosity_Pa_s(SyringeFluid fluid) {
  return fluid == SyringeFluid::kAir ? kAirViscosity_Pa_s : kSalineViscosity_Pa_s;
}

std::optional<MechanicsProblem> syringe_problem(const SyringeParams& p) {
  for (const auto& f : kSyringeFields) {
    const double value = p.*f.member;
    if (!(value > 0.0 && value <= f.max)) {
      char text[128];
      std::snprintf(text, sizeof text, "must be in (0, %g] %s, got %g", f.max, f.unit, value);
      return MechanicsProblem{f.key, text};
    }
  }
  return std::nullopt;
}

double syringe_stroke_m(const SyringeParams& p) { return p.fill_volume_m3 / p.plunger_area_m2; }

double lumen_resistance_Pa_s_per_m3(const SyringeParams& p) {
  const double r2 = p.lumen_radius_m * p.lumen_radius_m;
  return 8.0 * fluid_viscosity_Pa_s(p.fluid) * p.lumen_length_m / (std::numbers::pi * r2 * r2);
}

FlowPath flow_path(const SyringeParams& p, const LayerInjection* tip) {
  FlowPath path{0.0, lumen_resistance_Pa_s_per_m3(p)};
  if (tip == nullptr) return path;
  path.opening_pressure_Pa = tip->opening_pressure_Pa;
  path.resistance_Pa_s_per_m3 += tip->resistance_Pa_s_per_m3 * fluid_viscosity_Pa_s(p.fluid) / kSalineViscosity_Pa_s;
  return path;
}

}  // namespace needle::haptics
