#include "engine/ultrasound/echo_model.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace needle::engine::echo {
namespace {

constexpr double kNepersPerDecibel = 0.11512925464970229;  // ln(10) / 20

// The haptics' signed distances (haptics/constraints/implicit_surface.cpp), in glm.
LayerSample point_distance(const glm::dvec3& x, const glm::dvec3& c, double r) {
  const glm::dvec3 d = x - c;
  const double len = glm::length(d);
  if (len < 1e-12) return {-r, glm::dvec3(1.0, 0.0, 0.0)};
  return {len - r, d / len};
}

LayerSample evaluate_primitive(const EchoPrimitive& p, const glm::dvec3& x) {
  switch (p.kind) {
    case EchoPrimitive::Kind::Sphere:
      return point_distance(x, p.a, p.radius);
    case EchoPrimitive::Kind::Plane:
      return {glm::dot(p.b, x - p.a), p.b};
    case EchoPrimitive::Kind::Capsule: {
      const glm::dvec3 axis = p.b - p.a;
      const double len2 = glm::dot(axis, axis);
      const double t = len2 > 0.0 ? std::clamp(glm::dot(x - p.a, axis) / len2, 0.0, 1.0) : 0.0;
      return point_distance(x, p.a + t * axis, p.radius);
    }
  }
  return {0.0, glm::dvec3(1.0, 0.0, 0.0)};
}

// A grid's φ + offset and its normal (haptics/tissue/sdf_grid.cpp's, in glm: the same trilinear
// interpolant and the same rule outside the box).
LayerSample evaluate_grid(const EchoGrid& g, double offset, const glm::dvec3& x) {
  const glm::dvec3 hi = g.origin + g.spacing_m * glm::dvec3(g.nodes - glm::uvec3(1u));
  const glm::dvec3 p = glm::clamp(x, g.origin, hi);
  glm::ivec3 c;
  glm::dvec3 f;
  for (int a = 0; a < 3; ++a) {
    const double u = (p[a] - g.origin[a]) / g.spacing_m;
    c[a] = std::clamp(int(std::floor(u)), 0, int(g.nodes[a]) - 2);
    f[a] = std::clamp(u - c[a], 0.0, 1.0);
  }
  const auto v = [&](int i, int j, int k) {
    return double((*g.values)[(size_t(c.z + k) * g.nodes.y + size_t(c.y + j)) * g.nodes.x + size_t(c.x + i)]);
  };
  const double v000 = v(0, 0, 0), v100 = v(1, 0, 0), v010 = v(0, 1, 0), v110 = v(1, 1, 0);
  const double v001 = v(0, 0, 1), v101 = v(1, 0, 1), v011 = v(0, 1, 1), v111 = v(1, 1, 1);
  const double gx = 1.0 - f.x, gy = 1.0 - f.y, gz = 1.0 - f.z;
  const double value = gz * (gy * (gx * v000 + f.x * v100) + f.y * (gx * v010 + f.x * v110)) +
                       f.z * (gy * (gx * v001 + f.x * v101) + f.y * (gx * v011 + f.x * v111));
  const glm::dvec3 gradient(
      gz * (gy * (v100 - v000) + f.y * (v110 - v010)) + f.z * (gy * (v101 - v001) + f.y * (v111 - v011)),
      gz * (gx * (v010 - v000) + f.x * (v110 - v100)) + f.z * (gx * (v011 - v001) + f.x * (v111 - v101)),
      gy * (gx * (v001 - v000) + f.x * (v101 - v100)) + f.y * (gx * (v011 - v010) + f.x * (v111 - v110)));
  const double inside = g.quantum_m * value + offset;
  const glm::dvec3 out = x - p;
  const double gap = glm::length(out);
  if (gap > 0.0) return {gap + std::max(inside, 0.0), out / gap};
  const double len = glm::length(gradient);
  return {inside, len > 0.0 ? gradient / len : glm::dvec3(1.0, 0.0, 0.0)};
}

double impedance(const EchoScene& scene, int layer) {
  return layer < 0 ? kGelImpedance_MRayl : scene.layers[size_t(layer)].material.impedance_MRayl;
}

double time_gain(const UltrasoundProbe& probe, double depth_m) {
  return std::exp(2.0 * nepers_per_m(kTimeGain_dB_per_cm_MHz, probe.frequency_MHz) * depth_m);
}

// The depth in [z0, z1] where layer k's φ at the rest position changes sign, to a nanometre; the
// linear interpolation of its φ at the ends when it does not change sign there.
double crossing_depth(const EchoScene& scene, const DeformationField& field, int k, const glm::dvec3& origin,
                      const glm::dvec3& beam, double z0, double z1) {
  const auto phi = [&](double z) {
    return evaluate(scene.layers[size_t(k)], rest_position(field, origin + z * beam)).phi;
  };
  double lo = z0, hi = z1, phi_lo = phi(z0), phi_hi = phi(z1);
  if (phi_lo * phi_hi > 0.0 || phi_lo == phi_hi)
    return z0 + std::clamp(phi_lo / (phi_lo - phi_hi), 0.0, 1.0) * (z1 - z0);
  while (hi - lo > 1e-9) {
    const double mid = 0.5 * (lo + hi), phi_mid = phi(mid);
    if ((phi_mid < 0.0) == (phi_lo < 0.0))
      lo = mid, phi_lo = phi_mid;
    else
      hi = mid;
  }
  return 0.5 * (lo + hi);
}

ScanLine trace_line(const EchoScene& scene, const UltrasoundProbe& probe, const NeedleLoad* needle,
                    const UltrasoundSettings& settings, const DeformationField& field, uint32_t line) {
  ScanLine out;
  const glm::dvec3 origin = line_origin(probe, settings, line);
  const glm::dvec3 beam = probe.direction;
  std::optional<NeedleHit> hit;
  if (needle) hit = needle_hit(scene, probe, *needle, origin);
  if (hit) out.needle_depth_m = hit->depth_m;

  double amplitude = 1.0;  // round trip, without time-gain compensation
  int current = -1;
  double z_prev = 0.0;
  for (uint32_t j = 0; j < settings.samples; ++j) {
    const double z = sample_depth(probe, settings, j);
    const glm::dvec3 x = origin + z * beam;
    const glm::dvec3 rest = rest_position(field, x);
    const int layer = layer_at(scene, rest);
    if (layer != current) {
      const int k = deciding_layer(current, layer);
      if (out.interfaces.size() < ScanLine::kMaxInterfaces)
        out.interfaces.push_back({crossing_depth(scene, field, k, origin, beam, z_prev, z), current, layer});
      const double r = reflection(impedance(scene, current), impedance(scene, layer));
      amplitude *= 1.0 - r * r;
      current = layer;
    }
    if (hit && hit->depth_m > z_prev && hit->depth_m <= z) {
      const double r = reflection(impedance(scene, current), kNeedleImpedance_MRayl);
      amplitude *= 1.0 - r * r * hit->weight;
    }
    const double alpha = current < 0 ? 0.0
                                     : nepers_per_m(scene.layers[size_t(current)].material.attenuation_dB_per_cm_MHz,
                                                    probe.frequency_MHz);
    amplitude *= std::exp(-2.0 * alpha * (z - z_prev));
    if (std::isinf(out.shadow_depth_m) && amplitude * time_gain(probe, z) < kShadowLevel) out.shadow_depth_m = z;
    z_prev = z;
  }
  return out;
}

}  // namespace

double nepers_per_m(double dB_per_cm_MHz, double frequency_MHz) {
  return dB_per_cm_MHz * frequency_MHz * 100.0 * kNepersPerDecibel;
}

double reflection(double z1, double z2) { return (z2 - z1) / (z2 + z1); }

double specular_factor(const glm::dvec3& normal, const glm::dvec3& beam) {
  const double theta = std::acos(std::min(1.0, std::abs(glm::dot(normal, beam))));
  return std::exp(-(theta * theta) / (kSpecularWidth_rad * kSpecularWidth_rad));
}

glm::dvec3 line_origin(const UltrasoundProbe& probe, const UltrasoundSettings& settings, uint32_t line) {
  const double x = (double(line) + 0.5) / double(settings.lines) * probe.width_m - 0.5 * probe.width_m;
  return probe.position + x * probe.lateral;
}

double sample_depth(const UltrasoundProbe& probe, const UltrasoundSettings& settings, uint32_t sample) {
  return (double(sample) + 0.5) / double(settings.samples) * probe.depth_m;
}

LayerSample evaluate(const EchoLayer& layer, const glm::dvec3& x) {
  if (layer.grid) return evaluate_grid(*layer.grid, layer.grid_offset_m, x);
  LayerSample best{
      layer.intersection ? -std::numeric_limits<double>::infinity() : std::numeric_limits<double>::infinity(),
      glm::dvec3(1.0, 0.0, 0.0)};
  for (const EchoPrimitive& p : layer.primitives) {
    const LayerSample s = evaluate_primitive(p, x);
    if (layer.intersection ? s.phi > best.phi : s.phi < best.phi) best = s;
  }
  return best;
}

int layer_at(const EchoScene& scene, const glm::dvec3& x) {
  for (int k = int(scene.layers.size()) - 1; k >= 0; --k)
    if (evaluate(scene.layers[size_t(k)], x).phi < 0.0) return k;
  return -1;
}

DeformationField echo_field(const EchoScene& scene, const NeedleLoad* needle) {
  if (!scene.deformation || !needle) return {};
  return build_field(*needle, *scene.deformation);
}

glm::dvec3 rest_position(const DeformationField& field, const glm::dvec3& x, int iterations) {
  glm::dvec3 rest = x;
  if (field.empty()) return rest;
  for (int i = 0; i < iterations; ++i) {
    glm::dvec3 u(0.0);
    for (const Kelvinlet& k : field.loads) u += evaluate(k, field.material, rest).displacement;
    rest = x - u;
  }
  return rest;
}

uint32_t rest_node_spacing(const DeformationField& field, const UltrasoundSettings& settings, double sample_spacing_m) {
  if (settings.rest_node_spacing) return settings.rest_node_spacing;
  double curvature = 0.0;  // Σ_k 3|u_k(c_k)|/ε_k², per metre
  for (const Kelvinlet& k : field.loads)
    curvature += 3.0 * center_compliance(field.material, k.epsilon) * glm::length(k.force) / (k.epsilon * k.epsilon);
  uint32_t spacing = kMaxRestNodeSpacing;
  while (spacing > 1 && std::pow(spacing * sample_spacing_m, 2.0) / 8.0 * curvature > kRestTolerance_m) spacing /= 2;
  return spacing;
}

glm::dvec3 interpolated_rest_position(const DeformationField& field, const UltrasoundProbe& probe,
                                      const UltrasoundSettings& settings, uint32_t spacing,
                                      const glm::dvec3& line_origin, uint32_t j) {
  const uint32_t n = j / spacing;
  const auto offset = [&](uint32_t node) {
    const glm::dvec3 x = line_origin + sample_depth(probe, settings, node * spacing) * probe.direction;
    return rest_position(field, x) - x;
  };
  const double f = double(j - n * spacing) / double(spacing);
  return line_origin + sample_depth(probe, settings, j) * probe.direction + (1.0 - f) * offset(n) + f * offset(n + 1);
}

std::optional<NeedleHit> needle_hit(const EchoScene& scene, const UltrasoundProbe& probe, const NeedleLoad& needle,
                                    const glm::dvec3& line_origin) {
  const glm::dvec3 e = probe.elevation();
  const glm::dvec3 a = needle.axis, tip = needle.tip - line_origin;
  // The shaft S(t) = tip − t a, t in [0, length], in the line's frame: lateral offset X, depth Z, elevation E.
  const double x0 = glm::dot(tip, probe.lateral), z0 = glm::dot(tip, probe.direction), e0 = glm::dot(tip, e);
  const double al = glm::dot(a, probe.lateral), ad = glm::dot(a, probe.direction), ae = glm::dot(a, e);
  const double r = scene.needle.radius_m, length = scene.needle.length_m;
  // The shaft's point nearest the line in the plane across the beam (lateral, elevation): the
  // nearest approach of two lines, continuous as the needle turns through the image plane and so
  // one straight line of walls across the image. It echoes when it lies within its radius of the
  // line laterally; the elevation beam weighs its distance from the image plane.
  const double across2 = al * al + ae * ae;
  const double t = across2 > 1e-18 ? std::clamp((x0 * al + e0 * ae) / across2, 0.0, length) : 0.0;
  if (std::abs(x0 - t * al) > r) return std::nullopt;
  const double elevation = e0 - t * ae;
  const double sigma = probe.slice_thickness_m / 2.3548200450309493;  // FWHM → σ
  const double tilt = std::asin(std::min(1.0, std::abs(ad)));         // from the beam's normal plane
  const double weight = std::exp(-0.5 * elevation * elevation / (sigma * sigma)) *
                        std::exp(-(tilt * tilt) / (kSpecularWidth_rad * kSpecularWidth_rad));
  if (weight < 1e-3) return std::nullopt;
  const double wall = r / std::sqrt(std::max(1.0 - ad * ad, 1e-2));  // the near wall, along the beam
  return NeedleHit{z0 - t * ad - wall, weight};
}

double axial_sigma_m(const UltrasoundProbe& probe) {
  const double wavelength = kSoundSpeed_mps / (probe.frequency_MHz * 1e6);
  return kPulseCycles * wavelength / 2.0 / 2.3548200450309493;  // resolution cell = half the pulse, as FWHM
}

double lateral_sigma_m(const UltrasoundProbe& probe) {
  const double wavelength = kSoundSpeed_mps / (probe.frequency_MHz * 1e6);
  return wavelength * kFNumber / 2.3548200450309493;
}

}  // namespace needle::engine::echo

namespace needle::engine {

std::vector<ScanLine> trace_scan_lines(const EchoScene& scene, const UltrasoundProbe& probe, const NeedleLoad* needle,
                                       const UltrasoundSettings& settings) {
  const DeformationField field = echo::echo_field(scene, needle);
  std::vector<ScanLine> lines;
  lines.reserve(settings.lines);
  for (uint32_t i = 0; i < settings.lines; ++i)
    lines.push_back(echo::trace_line(scene, probe, needle, settings, field, i));
  return lines;
}

uint32_t rest_node_spacing(const EchoScene& scene, const UltrasoundProbe& probe, const NeedleLoad& needle,
                           const UltrasoundSettings& settings) {
  return echo::rest_node_spacing(echo::echo_field(scene, &needle), settings, probe.depth_m / settings.samples);
}

double rest_interpolation_error(const EchoScene& scene, const UltrasoundProbe& probe, const NeedleLoad& needle,
                                const UltrasoundSettings& settings) {
  const DeformationField field = echo::echo_field(scene, &needle);
  const uint32_t spacing = echo::rest_node_spacing(field, settings, probe.depth_m / settings.samples);
  double worst = 0.0;
  for (uint32_t i = 0; i < settings.lines; ++i) {
    const glm::dvec3 origin = echo::line_origin(probe, settings, i);
    for (uint32_t j = 0; j < settings.samples; ++j) {
      const glm::dvec3 exact =
          echo::rest_position(field, origin + echo::sample_depth(probe, settings, j) * probe.direction);
      worst = std::max(
          worst, glm::length(echo::interpolated_rest_position(field, probe, settings, spacing, origin, j) - exact));
    }
  }
  return worst;
}

}  // namespace needle::engine
