#include "haptics/sim/feel_metrics.hpp"

#include <algorithm>
#include <cmath>

namespace needle::haptics {
namespace {

// One second-order section (Bristow-Johnson's cookbook, Q = 1/√2: Butterworth), transposed direct form II.
struct Biquad {
  double b0, b1, b2, a1, a2;  // normalized by a0

  static Biquad butterworth(double sample_Hz, double corner_Hz, bool high_pass) {
    const double w0 = 2.0 * M_PI * corner_Hz / sample_Hz, c = std::cos(w0), alpha = std::sin(w0) / std::sqrt(2.0);
    const double a0 = 1.0 + alpha;
    const double b = high_pass ? (1.0 + c) / 2.0 : (1.0 - c) / 2.0;
    return {b / a0, (high_pass ? -2.0 : 2.0) * b / a0, b / a0, -2.0 * c / a0, (1.0 - alpha) / a0};
  }

  void run(std::vector<double>& x) const {
    double z1 = 0.0, z2 = 0.0;
    for (double& v : x) {
      const double y = b0 * v + z1;
      z1 = b1 * v - a1 * y + z2;
      z2 = b2 * v - a2 * y;
      v = y;
    }
  }
};

double rms(const std::vector<double>& sum_sq, const std::vector<bool>& counted) {
  double s = 0.0;
  long n = 0;
  for (size_t i = 0; i < sum_sq.size(); ++i)
    if (counted[i]) s += sum_sq[i], ++n;
  return n ? std::sqrt(s / double(n)) : 0.0;
}

FeelPhase phase_of(ContactMode mode) {
  switch (mode) {
    case ContactMode::Holonomic:
      return FeelPhase::Rigid;
    case ContactMode::Nonholonomic:
      return FeelPhase::Tissue;
    case ContactMode::Free:
      break;
  }
  return FeelPhase::Free;
}

}  // namespace

const char* feel_phase_name(FeelPhase phase) {
  switch (phase) {
    case FeelPhase::Free:
      return "free";
    case FeelPhase::Rigid:
      return "rigid contact";
    case FeelPhase::Tissue:
      return "tissue";
  }
  return "?";
}

std::vector<double> zero_phase_filter(const std::vector<double>& x, double sample_Hz, double corner_Hz,
                                      bool high_pass) {
  if (x.empty()) return {};
  const size_t pad = size_t(std::lround(sample_Hz));
  std::vector<double> y(pad, x.front());
  y.insert(y.end(), x.begin(), x.end());
  y.insert(y.end(), pad, x.back());
  const Biquad f = Biquad::butterworth(sample_Hz, corner_Hz, high_pass);
  f.run(y);
  std::reverse(y.begin(), y.end());
  f.run(y);
  std::reverse(y.begin(), y.end());
  return {y.begin() + long(pad), y.end() - long(pad)};
}

std::vector<PhaseFeel> feel_by_phase(const std::vector<TickRecord>& ticks, double period_s, const FeelWindows& w) {
  const double fs = 1.0 / period_s;
  const size_t n = ticks.size();
  // |F_h| band-passed and high-passed, per axis then squared and summed.
  std::vector<double> band_sq(n, 0.0), hf_sq(n, 0.0);
  for (int axis = 0; axis < 3; ++axis) {
    std::vector<double> f(n);
    for (size_t i = 0; i < n; ++i) f[i] = ticks[i].force_h[axis];
    const std::vector<double> band =
        zero_phase_filter(zero_phase_filter(f, fs, w.band_low_Hz, true), fs, w.band_high_Hz, false);
    const std::vector<double> hf = zero_phase_filter(f, fs, w.band_high_Hz, true);
    for (size_t i = 0; i < n; ++i) band_sq[i] += band[i] * band[i], hf_sq[i] += hf[i] * hf[i];
  }
  std::vector<PhaseFeel> out;
  for (FeelPhase phase : {FeelPhase::Free, FeelPhase::Rigid, FeelPhase::Tissue}) {
    std::vector<bool> counted(n, false);
    std::vector<double> tracking_sq(n);
    PhaseFeel p{phase};
    // Entry: the first tick in tissue after at least settle_out_s out of it (a tip flickering across
    // the surface does not enter again each time).
    double entered = -1.0, left = 0.0;
    bool was_in = false;
    long count = 0;
    for (size_t i = 0; i < n; ++i) {
      const TickRecord& r = ticks[i];
      tracking_sq[i] = r.position_error * r.position_error;
      const bool in = r.mode == ContactMode::Nonholonomic;
      if (in && !was_in && (entered < 0.0 || r.t - left >= w.settle_out_s)) entered = r.t;
      if (!in && was_in) left = r.t;
      was_in = in;
      if (phase_of(r.mode) != phase) continue;
      if (phase == FeelPhase::Tissue) {
        if (r.t - entered >= w.lateral_settle_s) {
          const double lateral = std::hypot(r.psi[0], r.psi[1]);
          p.max_lateral_speed_mps =
              std::isnan(p.max_lateral_speed_mps) ? lateral : std::max(p.max_lateral_speed_mps, lateral);
        }
        if (r.t - entered < w.tissue_settle_s) continue;
      }
      counted[i] = true;
      ++count;
    }
    if (count == 0) continue;
    p.seconds = double(count) * period_s;
    p.force_band_rms_N = rms(band_sq, counted);
    p.force_hf_rms_N = rms(hf_sq, counted);
    p.tracking_rms_m = rms(tracking_sq, counted);
    out.push_back(p);
  }
  return out;
}

double free_force_at_rest(Scenario scenario, double hold_s) {
  const HandTarget start = scenario.trajectory.at(0.0);
  scenario.trajectory = HandTrajectory({{0.0, start.position, start.direction}});
  scenario.duration_s = hold_s;
  double sum = 0.0;
  long count = 0;
  run_closed_loop(scenario, false, [&](const TickRecord& r) {
    if (r.t > hold_s / 2) sum += r.force_h.norm(), ++count;
  });
  return count ? sum / double(count) : 0.0;
}

}  // namespace needle::haptics
