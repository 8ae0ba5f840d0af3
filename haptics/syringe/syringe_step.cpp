#include "haptics/syringe/syringe_step.hpp"

#include <algorithm>
#include <cmath>

namespace needle::haptics {
namespace {

// The gas's volume with the plunger at `travel`.
double gas_volume(const SyringeParams& p, double travel) {
  return p.fill_volume_m3 + kSyringeDeadVolume_m3 - p.plunger_area_m2 * travel;
}

// Saline: v = max(0, F − A p_o)/(b + A² R), the plunger stopping at the barrel's end; the barrel's
// pressure p_o + R A v while the fluid flows, F/A while the thumb holds it still, 0 once empty.
void step_saline(const SyringeParams& p, SyringeState& s, double force, const FlowPath& path, double dt) {
  const double area = p.plunger_area_m2, stroke = syringe_stroke_m(p);
  const double drive = force - area * path.opening_pressure_Pa;
  double v = drive > 0.0 ? drive / (p.thumb_damping_Ns_per_m + area * area * path.resistance_Pa_s_per_m3) : 0.0;
  v = std::min(v, (stroke - s.travel_m) / dt);
  const bool empty = s.travel_m >= stroke;
  s.pressure_Pa = empty     ? 0.0
                  : v > 0.0 ? path.opening_pressure_Pa + path.resistance_Pa_s_per_m3 * area * v
                            : force / area;
  s.flow_m3_per_s = area * v;
  s.plunger_force_N = area * s.pressure_Pa;
  s.work_J += s.plunger_force_N * v * dt;
  s.travel_m = std::min(s.travel_m + v * dt, stroke);
  s.injected_m3 += area * v * dt;
}

// Air, in two implicit stages. Compression at constant content m: F − b v = A (m / (V − A v dt) − p₀),
// i.e. (G − b v)(V − a v) = A m with G = F + A p₀, a = A dt, whose root with both factors positive
// is the smaller one. Then the leak at the new volume V': P (V' + Q(P) dt) = m, Q = max(0, P − p₀ − p_o)/R,
// a quadratic in the absolute pressure P above the opening.
void step_air(const SyringeParams& p, SyringeState& s, double force, const FlowPath& path, double dt) {
  const double area = p.plunger_area_m2, b = p.thumb_damping_Ns_per_m, stroke = syringe_stroke_m(p);
  const double m = s.gas_J, volume = gas_volume(p, s.travel_m);
  const double g = force + area * kAmbientPressure_Pa, a = area * dt;
  const double linear = g * a + b * volume, constant = g * volume - area * m;
  const double discriminant = (g * a - b * volume) * (g * a - b * volume) + 4.0 * a * b * area * m;
  double v = 2.0 * constant / (linear + std::sqrt(discriminant));  // the smaller root, without cancellation
  const double travel = std::clamp(s.travel_m + v * dt, 0.0, stroke);
  v = (travel - s.travel_m) / dt;
  const double compressed_volume = gas_volume(p, travel);
  const double compressed = m / compressed_volume;  // absolute, before the leak
  s.plunger_force_N = area * (compressed - kAmbientPressure_Pa);
  s.work_J += s.plunger_force_N * v * dt;
  s.travel_m = travel;

  const double threshold = kAmbientPressure_Pa + path.opening_pressure_Pa;
  double absolute = compressed, flow = 0.0;
  if (compressed > threshold) {
    const double c = dt / path.resistance_Pa_s_per_m3, d = compressed_volume - c * threshold;
    absolute = 2.0 * m / (d + std::sqrt(d * d + 4.0 * c * m));  // the positive root, without cancellation
    flow = (absolute - threshold) / path.resistance_Pa_s_per_m3;
  }
  s.gas_J = absolute * compressed_volume;
  s.injected_m3 += (m - s.gas_J) / kAmbientPressure_Pa;
  s.pressure_Pa = absolute - kAmbientPressure_Pa;
  s.flow_m3_per_s = flow;
}

}  // namespace

SyringeState syringe_at_rest(const SyringeParams& params) {
  SyringeState s;
  if (params.fluid == SyringeFluid::kAir) s.gas_J = kAmbientPressure_Pa * gas_volume(params, 0.0);
  return s;
}

void step_syringe(const SyringeParams& params, SyringeState& state, double thumb_force_N, const FlowPath& path,
                  double dt) {
  const double force = thumb_force_N > 0.0 ? thumb_force_N : 0.0;  // NaN too
  state.thumb_force_N = force;
  if (params.fluid == SyringeFluid::kAir)
    step_air(params, state, force, path, dt);
  else
    step_saline(params, state, force, path, dt);
}

double syringe_stored_energy(const SyringeParams& params, const SyringeState& state) {
  if (params.fluid != SyringeFluid::kAir || !(state.gas_J > 0.0)) return 0.0;
  const double m = state.gas_J, ambient = kAmbientPressure_Pa * gas_volume(params, state.travel_m);
  return m * std::log(m / ambient) - m + ambient;
}

}  // namespace needle::haptics
