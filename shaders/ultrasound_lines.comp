#version 450
// Scan lines: one work item a line finds where its layer changes and what happens there, without
// visiting every sample: a layer evaluated at a sample at a clearance c from its surface (below)
// holds or misses every sample nearer than c alike, so the walk evaluates each layer again only
// where its clearance runs out. At each change it reflects (the crossing placed between its two
// samples where the crossed surface's φ changes sign), and at the needle's wall with its
// reverberation tail; it writes the runs of samples between those events with their amplitudes,
// and the specular echoes, for ultrasound_echoes.comp to turn into every sample's echo. Samples
// for samples, the CPU reference's walk (engine/ultrasound/echo_model.cpp, trace_scan_lines).
#extension GL_GOOGLE_include_directive : require
#define ECHO_IN_STORAGE_BUFFER
#include "ultrasound.glsl"

layout(local_size_x = 8) in;

float impedance(int layer) { return layer < 0 ? echo.media.x : layers[layer].material.x; }
float reflection(float z1, float z2) { return (z2 - z1) / (z2 + z1); }
float specular_factor(vec3 normal) {
  float theta = acos(min(1.0, abs(dot(normal, echo.direction.xyz))));
  return exp(-(theta * theta) / (echo.beam.w * echo.beam.w));
}
float attenuation(int layer) { return layer < 0 ? 0.0 : layers[layer].material.y * echo.beam.x; }

// Where the line meets the needle's near wall and the echo's weight, 0 when it misses it
// (echo_model.cpp, needle_hit).
vec2 needle_hit(vec3 origin) {
  if (echo.needle_tip.w == 0.0) return vec2(0.0);
  vec3 a = echo.needle_axis.xyz, tip = echo.needle_tip.xyz - origin;
  float x0 = dot(tip, echo.lateral.xyz), z0 = dot(tip, echo.direction.xyz), e0 = dot(tip, echo.elevation.xyz);
  float al = dot(a, echo.lateral.xyz), ad = dot(a, echo.direction.xyz), ae = dot(a, echo.elevation.xyz);
  float r = echo.needle.x;
  float across2 = al * al + ae * ae;
  float t = across2 > 1e-18 ? clamp((x0 * al + e0 * ae) / across2, 0.0, echo.needle_axis.w) : 0.0;
  if (abs(x0 - t * al) > r) return vec2(0.0);
  float elevation = e0 - t * ae;
  float tilt = asin(min(1.0, abs(ad)));
  float weight = exp(-0.5 * elevation * elevation / (echo.needle.y * echo.needle.y)) * exp(-(tilt * tilt) / (echo.beam.w * echo.beam.w));
  if (weight < 1e-3) return vec2(0.0);
  float wall = r / sqrt(max(1.0 - ad * ad, 1e-2));
  return vec2(z0 - t * ad - wall, weight);
}

// Whether layer k holds x, and its clearance: how far along the beam from x its membership cannot
// change. A primitive's |φ| is its distance (spheres, capsules, planes); at rest a plane is crossed
// only where the beam meets it. A grid's nodes hold a distance (or a lower bound of one), so its
// trilinear interpolant's partial derivatives are each at most 1 + quantum/spacing (a blend of
// node differences of at most a spacing and a quantum each; docs/TISSUE.md): along a beam d it
// changes at most |d|₁ = |dx| + |dy| + |dz| (1 to √3) times that fast. While the tissue is deformed
// the beam is curved in rest space, any direction: 2√3 times (the rest position moves up to twice
// as fast as the point for a displacement gradient up to 0.5, a design value; docs/RENDERING.md,
// "How the passes find the layers"), and a primitive's clearance half its |φ|.
bool holds(uint k, vec3 x, vec3 beam, out float clearance) {
  bool at_rest = LOADS == 0u;
  uvec4 shape = layers[k].shape;
  if (shape.w != 0u) {
    uint g = shape.w - 1u;
    float s = evaluate_grid(g, layers[k].grid.x, x).phi;
    float rate = at_rest ? abs(beam.x) + abs(beam.y) + abs(beam.z) : 3.4641016;
    clearance = abs(s) / (rate * (1.0 + grids[g].quantum.x / grids[g].origin_spacing.w));
    return s < 0.0;
  }
  bool intersection = shape.z == 1u;
  float phi = intersection ? -1e30 : 1e30;
  clearance = 1e30;
  for (uint i = 0; i < shape.y; ++i) {
    Primitive p = primitives[shape.x + i];
    float s = evaluate_primitive(p, x).phi;
    phi = intersection ? max(phi, s) : min(phi, s);
    float c = abs(s);
    if (!at_rest) {
      c *= 0.5;
    } else if (int(p.a_kind.w) == 1) {
      float approach = dot(p.b_radius.xyz, beam);  // φ's rate along the beam
      c = s * approach < 0.0 ? -s / approach : s == 0.0 ? 0.0 : 1e30;
    }
    clearance = min(clearance, c);
  }
  return phi < 0.0;
}

// The walk's knowledge of each layer k < 16: bit k of `inside`, whether it held the sample where it
// was last evaluated, and due[k], the first sample where that may have changed (its clearance runs
// out there; 0xffffffff past the scene's layers). The loops run over all 16 with constant indices,
// so that a CPU device (lavapipe) keeps the array in registers.
uint due[16];
uint inside = 0u;

// At sample `at`: the last layer known to hold it (-1: none), and the last layer after that whose
// membership there is not known (-1: none, the sample's layer is `known`). The layers before a
// layer that holds the sample do not decide it, so they are not needed.
void decide(uint at, out int known, out int unknown) {
  uint valid = 0u;  // the layers whose membership at `at` is known
  for (int k = 0; k < 16; ++k) valid |= due[k] > at ? 1u << k : 0u;
  known = findMSB(valid & inside);
  uint after = 0xffffu & ~((1u << uint(known + 1)) - 1u);  // the layers after `known`
  unknown = findMSB(~valid & after);
}

// The first sample where the layers from `known` on may change: the sample after the run of
// samples in layer `known`.
uint run_end(int known) {
  uint end = 0xffffffffu;
  for (int k = 0; k < 16; ++k) end = k >= known ? min(end, due[k]) : end;
  return end;
}

// The sample whose interval (depth(j − 1), depth(j)] holds `depth` (> 0).
uint sample_holding(float depth) { return uint(max(ceil(depth / echo.image.z - 0.5), 0.0)); }

uint line;
Run run;  // the run the walk is in

// The round-trip amplitude arriving at sample j's interval: the run's, attenuated down to its start.
float amplitude_into(uint j) { return run.amplitude * exp(-2.0 * run.alpha * (interval_start(j) - interval_start(run.first))); }

// An echo at a depth in sample j's interval (depth(j − 1), depth(j)]: the share f to sample j,
// 1 − f to the one before (the whole echo to sample 0); none past the last sample.
void add_specular(uint j, float f, float amplitude) {
  uint samples = echo.counts.y;
  if (j >= samples) return;
  ivec2 at = ivec2(j, line);
  imageStore(echoes, at, imageLoad(echoes, at) + vec4((j == 0u ? 1.0 : f) * amplitude, 0.0, 0.0, 0.0));
  if (j > 0u) {
    ivec2 before = ivec2(j - 1u, line);
    imageStore(echoes, before, imageLoad(echoes, before) + vec4((1.0 - f) * amplitude, 0.0, 0.0, 0.0));
  }
}

// The first sample in shadow (its compensated round-trip amplitude below the shadow level), if
// it lies in the current run before `end`: the amplitude's log is linear in depth along a run.
uint shadow = 0xffffffffu;
void find_shadow(uint end) {
  if (shadow != 0xffffffffu || run.first >= end) return;
  float z_first = sample_depth(run.first);
  float level = log(echo.media.w);
  float at_first = log(max(run.amplitude, 1e-37)) - 2.0 * run.alpha * (z_first - interval_start(run.first)) +
                   2.0 * echo.beam.y * z_first;
  if (at_first < level) {
    shadow = run.first;
    return;
  }
  float slope = 2.0 * (echo.beam.y - run.alpha);  // per metre of depth
  if (slope >= 0.0) return;
  float reached = z_first + (level - at_first) / slope;  // the depth where it meets the level
  float first_below = floor(reached / echo.image.z - 0.5) + 1.0;  // the first sample deeper
  if (first_below < float(end)) shadow = uint(max(first_below, float(run.first)));
}

// A new run from sample j (the current one replaced when it begins there too).
void begin_run(uint j, int layer, float amplitude) {
  uint n = lines[line].run_count;
  if (run.first == j && n > 0u) --n;
  else if (n >= MAX_RUNS) return;  // past the limit the last run goes on
  find_shadow(j);
  run = Run(j, layer, amplitude, attenuation(layer));
  store_run(line, n, run);
  lines[line].run_count = n + 1u;
}

void main() {
  line = gl_GlobalInvocationID.x;
  if (line >= echo.counts.x) return;
  uint samples = echo.counts.y;
  vec3 beam = echo.direction.xyz;
  vec3 origin = line_origin(line);
  vec2 hit = needle_hit(origin);
  uint needle_sample = hit.y > 0.0 && hit.x > 0.0 ? sample_holding(hit.x) : samples;

  lines[line].needle_depth = hit.x;
  lines[line].needle_weight = hit.y;
  lines[line].sample_spacing = echo.image.z;
  lines[line].run_count = 1u;
  run = Run(0u, -1, 1.0, 0.0);
  store_run(line, 0u, run);
  for (uint i = 0u; i < 16u; ++i) due[i] = i < echo.counts.z ? 0u : 0xffffffffu;
  uint count = 0u;
  int current = -1;
  uint from = 0u;  // the sample the current layer begins at
  uint at = 0u;    // the walk's frontier: every sample before it has its layer
  for (;;) {
    // The next sample whose layer differs from the current one (samples: none). A layer is
    // evaluated only where its clearance runs out and the sample's layer depends on it: the last
    // layer not known to miss it, until one is known to hold it. So a layer far from every sample
    // is evaluated a few times down the line, one the line crosses at every sample near it, and
    // none of those before the layer the line is in.
    uint change = samples;
    int layer = current;
    for (;;) {
      int known, unknown;
      decide(at, known, unknown);
      if (unknown < 0) {  // the sample's layer is known
        if (known != current) {
          change = at;
          layer = known;
          break;
        }
        at = run_end(known);
        if (at >= samples) break;
        decide(at, known, unknown);  // a layer from `known` on is due there: not known
      }
      float clearance;
      bool in_k = holds(uint(unknown), rest_position(origin + sample_depth(at) * beam), beam, clearance);
      inside = in_k ? inside | (1u << unknown) : inside & ~(1u << unknown);
      // Samples nearer than the clearance share this one's membership; 0.01 sample of margin for
      // float rounding. At least the next sample, whatever the float (a NaN's conversion is
      // undefined): the walk always moves on.
      uint again = at + max(uint(clamp(ceil(clearance / echo.image.z - 0.01), 1.0, float(samples))), 1u);
      for (int k = 0; k < 16; ++k) due[k] = k == unknown ? again : due[k];
    }
    if (needle_sample >= from && needle_sample < change) {
      // The needle's wall, in the current layer.
      float z_prev = interval_start(needle_sample);
      float span = sample_depth(needle_sample) - z_prev;
      float r = reflection(impedance(current), echo.media.y);
      float incoming = amplitude_into(needle_sample);
      float echo_amplitude = incoming * abs(r) * hit.y * time_gain(hit.x);
      add_specular(needle_sample, (hit.x - z_prev) / span, echo_amplitude);
      float tail = echo_amplitude;
      for (int n = 1; n <= int(echo.needle.z); ++n) {
        tail *= echo.media.z;
        float tail_depth = hit.x + 2.0 * float(n) * echo.needle.x;
        uint at = max(sample_holding(tail_depth), needle_sample);
        float at_start = interval_start(at);
        add_specular(at, clamp((tail_depth - at_start) / (sample_depth(at) - at_start), 0.0, 1.0), tail);
      }
      begin_run(needle_sample, current, incoming * (1.0 - r * r * hit.y));
    }
    if (change >= samples) break;
    // The interface: placed where the surface of the layer that decides (the deeper in the
    // order of the two) crosses φ = 0 between the sample before and this one.
    int k = layer > current ? layer : current;
    float z = sample_depth(change), z_prev = interval_start(change);
    float phi0 = evaluate_layer(uint(k), rest_position(origin + z_prev * beam)).phi;
    LayerSample s1 = evaluate_layer(uint(k), rest_position(origin + z * beam));
    float f = phi0 != s1.phi ? clamp(phi0 / (phi0 - s1.phi), 0.0, 1.0) : 0.0;
    float depth = z_prev + f * (z - z_prev);
    if (count < MAX_INTERFACES) lines[line].interfaces[count++] = Interface(depth, current, layer, 0.0);
    float r = reflection(impedance(current), impedance(layer));
    float incoming = amplitude_into(change);
    add_specular(change, f, incoming * abs(r) * specular_factor(s1.normal) * time_gain(depth));
    begin_run(change, layer, incoming * (1.0 - r * r));
    current = layer;
    from = change;
  }
  find_shadow(samples);
  lines[line].shadow_sample = shadow;
  lines[line].count = count;
}
