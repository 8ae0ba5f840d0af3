// The scan-line model's constants and geometry, shared by the CPU reference (echo_model.cpp,
// double precision) and the GPU pass, which hands them to shaders/ultrasound_lines.comp and
// ultrasound_echoes.comp. The equations and where each number comes from: docs/RENDERING.md,
// "Ultrasound".
#pragma once

#include <glm/glm.hpp>
#include <optional>

#include "engine/deformation/deformation_field.hpp"
#include "engine/ultrasound.hpp"

namespace needle::engine::echo {

constexpr double kSoundSpeed_mps = 1540.0;                 // the scanner's assumed speed of sound in tissue
constexpr double kBackscatterLevel = 0.05;                 // −26 dB: echogenicity 1 against a perfect reflector
constexpr double kTimeGain_dB_per_cm_MHz = 0.8;            // time-gain compensation, one way
constexpr double kSpecularWidth_rad = 0.5235987755982988;  // 30°: exp(−θ²/w²) of the angle to the normal
constexpr double kGelImpedance_MRayl = 1.5;                // coupling gel, outside every layer (water-like)
constexpr double kNeedleImpedance_MRayl = 45.0;            // stainless steel, ρc = 7900 kg/m³ × 5700 m/s
constexpr double kReverberationRatio = 0.3;                // each echo of the needle's tail against the last (−10 dB)
constexpr int kReverberationEchoes = 4;
constexpr double kShadowLevel = 0.01;      // −40 dB: where a line's shadow begins
constexpr double kPulseCycles = 2.0;       // the pulse's length in wavelengths
constexpr double kFNumber = 2.0;           // lateral resolution = λ × F-number
constexpr double kScattererCell_m = 1e-4;  // the scatterer field's grid
constexpr int kRestIterations = 4;         // fixed-point steps from deformed to rest position
constexpr int kMaxKernelRadius = 16;       // samples (or lines) either side of the PSF's centre

// Nepers per metre, one way, of α dB/(cm·MHz) at f MHz.
double nepers_per_m(double dB_per_cm_MHz, double frequency_MHz);
// Amplitude reflection coefficient from impedance z1 into z2.
double reflection(double z1, double z2);
// exp(−θ²/w²), θ the angle between the beam and the surface's normal (either side).
double specular_factor(const glm::dvec3& normal, const glm::dvec3& beam);

// Line i's origin on the probe's face; sample j's depth (the middle of its interval).
glm::dvec3 line_origin(const UltrasoundProbe& probe, const UltrasoundSettings& settings, uint32_t line);
double sample_depth(const UltrasoundProbe& probe, const UltrasoundSettings& settings, uint32_t sample);

// A layer's signed distance (φ < 0 inside) and its gradient (the outward normal).
struct LayerSample {
  double phi;
  glm::dvec3 normal;
};
LayerSample evaluate(const EchoLayer& layer, const glm::dvec3& x);
// The last layer whose region holds x, -1 in none.
int layer_at(const EchoScene& scene, const glm::dvec3& x);
// Which layer's surface a step from layer `from` to layer `to` crossed: entering a later layer
// crosses its surface, leaving one (to an earlier layer or none) crosses the one left.
inline int deciding_layer(int from, int to) { return to > from ? to : from; }

// The tissue field of the needle's state (empty without deformation or needle).
DeformationField echo_field(const EchoScene& scene, const NeedleLoad* needle);
// The rest position whose displaced position is x: X = x − u(X) by fixed-point iteration.
glm::dvec3 rest_position(const DeformationField& field, const glm::dvec3& x, int iterations = kRestIterations);
// The rest nodes' spacing in samples: the settings' own, or for 0 (automatic) the one for this
// field sampled every `sample_spacing_m` down the lines: the largest power of two up to
// kMaxRestNodeSpacing whose interpolation error estimate, h²/8 · Σ_k 3|u_k(c_k)|/ε_k², stays
// within kRestTolerance_m (1 when none does). Linear interpolation between nodes h apart errs by
// h²/8 times the second derivative; a regularized Kelvinlet's 1/r_ε profile has |u''| = |u|/ε² at
// its centre, and the factor 3 covers its window's share and the inverse map's (checked against
// the exact error, engine::rest_interpolation_error: tests/engine/test_ultrasound.cpp, bench
// ultrasound's rest_error_m).
constexpr double kRestTolerance_m = kScattererCell_m / 50.0;  // design value: 2 µm, far below a sample (≥ 98 µm)
constexpr uint32_t kMaxRestNodeSpacing = 16;
uint32_t rest_node_spacing(const DeformationField& field, const UltrasoundSettings& settings, double sample_spacing_m);
// Sample j's rest position on a line as the GPU finds it (shaders/ultrasound.glsl, rest_of_sample):
// the offsets rest − x at the nodes `spacing` samples apart, linearly interpolated.
glm::dvec3 interpolated_rest_position(const DeformationField& field, const UltrasoundProbe& probe,
                                      const UltrasoundSettings& settings, uint32_t spacing,
                                      const glm::dvec3& line_origin, uint32_t j);

// Where a scan line meets the needle's near wall, and how strongly the wall sends the echo back:
// the elevation beam's weight at the needle's offset from the image plane times the specular
// factor of its angle to the beam.
struct NeedleHit {
  double depth_m;
  double weight;
};
std::optional<NeedleHit> needle_hit(const EchoScene& scene, const UltrasoundProbe& probe, const NeedleLoad& needle,
                                    const glm::dvec3& line_origin);

// The point spread function's Gaussian widths (standard deviations), metres.
double axial_sigma_m(const UltrasoundProbe& probe);
double lateral_sigma_m(const UltrasoundProbe& probe);

}  // namespace needle::engine::echo
