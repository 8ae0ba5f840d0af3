// What the ultrasound passes share (engine/ultrasound/ultrasound_pass.cpp mirrors it, std140
// and std430): the frame's probe, needle and display settings, and the buffers between the passes.
// The model: docs/RENDERING.md, "Ultrasound"; its double-precision reference:
// engine/ultrasound/echo_model.cpp.
#include "kelvinlet.glsl"

#define MAX_LOADS 8
#define KERNEL_VEC4S 5  // up to 17 weights (radius 16) of the point spread function, 4 to a vec4

// The line pass reads the block as a storage buffer (binding 7, the same memory): lavapipe (Mesa
// 22.3) recompiles a shader whose branches test uniform-block values with those values inlined
// each time the block is bound, that is every image, and the line pass's branches test many
// (the needle's direction, the loads, the layers); it inlines nothing from storage buffers.
#ifdef ECHO_IN_STORAGE_BUFFER
layout(set = 0, binding = 7, std140) readonly buffer Echo {
#else
layout(set = 0, binding = 0, std140) uniform Echo {
#endif
  vec4 origin;       // xyz: the probe face's centre
  vec4 direction;    // xyz: the beams' direction
  vec4 lateral;      // xyz: along the array
  vec4 elevation;    // xyz: direction × lateral
  vec4 image;        // x depth, y width, z sample spacing, w line spacing (m)
  uvec4 counts;      // x lines, y samples, z layers, w loads (the shaders' LOADS)
  uvec4 kernel;      // x axial radius (samples), y lateral radius (lines) (AXIAL_RADIUS, LATERAL_RADIUS), z speckle (0/1), w rest nodes' spacing (samples)
  vec4 beam;         // x Np/m per dB/(cm MHz) at the probe's frequency, y time gain (Np/m, one way), z backscatter level, w specular width (rad)
  vec4 media;        // x gel impedance, y needle impedance, z reverberation ratio, w shadow level
  vec4 needle_tip;   // xyz, w: 1 when there is a needle
  vec4 needle_axis;  // xyz unit, w shaft length
  vec4 needle;       // x radius, y elevation σ, z reverberation echoes
  vec4 display;      // x dynamic range (dB), y gain (dB), z speckle normalisation, w scatterer cell (m)
  vec4 material;     // x a, y b of the tissue's Kelvinlets
  vec4 axial_weights[KERNEL_VEC4S];    // exp(−(kΔz)²/2σ²), k = 0..radius
  vec4 lateral_weights[KERNEL_VEC4S];
  Load loads[MAX_LOADS];
} echo;

// The scene's layers, outside in, and their primitives or grids (engine/ultrasound.hpp, EchoLayer).
struct Layer {
  uvec4 shape;    // x first primitive, y count, z 1 intersection / 0 union, w grid + 1 (0: primitives)
  vec4 material;  // x impedance (MRayl), y attenuation (dB/(cm MHz)), z echogenicity, w scatterer density
  vec4 grid;      // x the grid's offset (m)
};
struct Grid {
  vec4 origin_spacing;  // xyz origin, w spacing (m)
  uvec4 nodes_first;    // xyz node counts, w its first value in grid_words
  vec4 quantum;         // x quantum (m)
};
struct Primitive {
  vec4 a_kind;    // xyz a, w kind: 0 sphere, 1 plane, 2 capsule
  vec4 b_radius;  // xyz b, w radius
};
// A uniform block, not a storage buffer: a CPU device (lavapipe) reads a uniform the work items
// share once for all its SIMD lanes, where it reads a storage buffer lane by lane.
layout(set = 0, binding = 1, std140) uniform Layers {
  Layer layers[16];
  Primitive primitives[128];
  Grid grids[16];
};
// The grids' values, 16-bit whole quanta, two to a word (engine/ultrasound/ultrasound_pass.cpp, grid_values).
layout(set = 0, binding = 9, std430) readonly buffer GridValues { uint grid_words[]; };

// Per sample (x) of each line (y): its received echo (xy: in-phase, quadrature): the specular
// echoes (interfaces, needle wall, reverberation) the line pass adds to the cleared image, then
// the tissue's the per-sample pass adds; then that echo after the axial convolution. Per scan
// line, what it met (engine/ultrasound.hpp, ScanLine) and what the per-sample pass needs to make
// its echoes without walking the line again: the runs of samples between the line's events (an
// interface, the needle's wall), each with its layer and the round-trip amplitude it starts with.
// Storage images, not buffers: a CPU device (lavapipe) reads and writes an image for all its SIMD
// lanes at once, a storage buffer lane by lane; the echoes two-channel (rg32f), which halves what
// the convolutions read.
layout(set = 0, binding = 2, rg32f) uniform image2D echoes;
layout(set = 0, binding = 3, rg32f) uniform image2D axial;
// The per-sample passes' work item does one sample of this many neighbouring lines: a CPU device
// (lavapipe) pays for every SIMD group of work items it starts, as much as a few samples' arithmetic
// (docs/BENCHMARKS.md, "Ultrasound image"). engine/ultrasound/ultrasound_pass.cpp kLinesPerItem.
#define LINES_PER_ITEM 16
#define MAX_INTERFACES 24
#define MAX_RUNS 32
struct Interface {
  float depth;
  int from_layer;
  int to_layer;
  float pad;
};
// Samples [first, next run's first) lie in `layer`; the round-trip amplitude at sample j of the
// run is amplitude · exp(−2 alpha (depth(j) − start)), start the depth the run's attenuation
// begins at (the previous sample's, 0 for the first). Kept in `runs` (x: the run, y: the line) as
// (first, layer, amplitude, alpha).
struct Run {
  uint first;
  int layer;
  float amplitude;
  float alpha;
};
layout(set = 0, binding = 6, rgba32f) uniform image2D runs;
void store_run(uint line, uint n, Run r) {
  imageStore(runs, ivec2(n, line), vec4(float(r.first), float(r.layer), r.amplitude, r.alpha));
}
Run load_run(uint line, uint n) {
  vec4 r = imageLoad(runs, ivec2(n, line));
  return Run(uint(r.x), int(r.y), r.z, r.w);
}
struct LineRecord {
  uint count;
  uint shadow_sample;   // the first sample in shadow; 0xffffffff: none
  float needle_depth;
  float needle_weight;  // 0: the line misses the needle
  uint run_count;
  float sample_spacing;
  uint pad0, pad1;
  Interface interfaces[MAX_INTERFACES];
};
layout(set = 0, binding = 4, std430) buffer Lines { LineRecord lines[]; };
layout(set = 0, binding = 5, rgba8) uniform writeonly image2D picture;
// A deformed tissue's rest positions as offsets from the samples' (xyz: rest − x) at nodes every
// echo.kernel.w samples down each line (x: the node, n at sample n·kernel.w, up to the first at
// or past the last sample; y: the line), made by ultrasound_rest.comp; the per-sample pass
// interpolates between them instead of undoing the displacement at every sample (rest_of_sample).
layout(set = 0, binding = 8, rgba32f) uniform image2D rest_offsets;

// The line's origin on the probe's face (echo_model.cpp, line_origin) and a sample's depth.
vec3 line_origin(uint line) {
  return echo.origin.xyz + ((float(line) + 0.5) * echo.image.w - 0.5 * echo.image.y) * echo.lateral.xyz;
}
float sample_depth(uint j) { return (float(j) + 0.5) * echo.image.z; }
// Where sample j's interval begins: the previous sample's depth, the face's for the first.
float interval_start(uint j) { return j == 0u ? 0.0 : sample_depth(j - 1u); }
// Time-gain compensation of the round trip to `depth`.
float time_gain(float depth) { return exp(2.0 * echo.beam.y * depth); }

// The layers' signed distances (the haptics' implicit surfaces; echo_model.cpp, evaluate).
struct LayerSample {
  float phi;
  vec3 normal;
};

LayerSample point_distance(vec3 x, vec3 c, float r) {
  vec3 d = x - c;
  float len = length(d);
  if (len < 1e-12) return LayerSample(-r, vec3(1.0, 0.0, 0.0));
  return LayerSample(len - r, d / len);
}

LayerSample evaluate_primitive(Primitive p, vec3 x) {
  int kind = int(p.a_kind.w);
  if (kind == 1) return LayerSample(dot(p.b_radius.xyz, x - p.a_kind.xyz), p.b_radius.xyz);
  if (kind == 2) {
    vec3 axis = p.b_radius.xyz - p.a_kind.xyz;
    float len2 = dot(axis, axis);
    float t = len2 > 0.0 ? clamp(dot(x - p.a_kind.xyz, axis) / len2, 0.0, 1.0) : 0.0;
    return point_distance(x, p.a_kind.xyz + t * axis, p.b_radius.w);
  }
  return point_distance(x, p.a_kind.xyz, p.b_radius.w);
}

// Value i of the grids' buffer, sign-extended from its 16 bits.
float grid_value(uint i) {
  uint word = grid_words[i >> 1];
  return float((i & 1u) == 0u ? int(word << 16) >> 16 : int(word) >> 16);
}

// A grid's φ + offset and its normal (echo_model.cpp, evaluate_grid): trilinear, the gradient
// normalised; outside the box, the distance to it plus the nearest box point's positive φ.
LayerSample evaluate_grid(uint g, float offset, vec3 x) {
  vec3 lo = grids[g].origin_spacing.xyz;
  float h = grids[g].origin_spacing.w;
  uvec3 n = grids[g].nodes_first.xyz;
  vec3 p = clamp(x, lo, lo + h * vec3(n - 1u));
  vec3 u = (p - lo) / h;
  ivec3 c = clamp(ivec3(floor(u)), ivec3(0), ivec3(n) - 2);
  vec3 f = clamp(u - vec3(c), 0.0, 1.0);
  uint base = grids[g].nodes_first.w + (uint(c.z) * n.y + uint(c.y)) * n.x + uint(c.x);
  uint sy = n.x, sz = n.x * n.y;
  float v000 = grid_value(base), v100 = grid_value(base + 1u), v010 = grid_value(base + sy), v110 = grid_value(base + sy + 1u);
  float v001 = grid_value(base + sz), v101 = grid_value(base + sz + 1u), v011 = grid_value(base + sz + sy), v111 = grid_value(base + sz + sy + 1u);
  vec3 gf = 1.0 - f;
  float value = gf.z * (gf.y * (gf.x * v000 + f.x * v100) + f.y * (gf.x * v010 + f.x * v110)) +
                f.z * (gf.y * (gf.x * v001 + f.x * v101) + f.y * (gf.x * v011 + f.x * v111));
  vec3 gradient = vec3(gf.z * (gf.y * (v100 - v000) + f.y * (v110 - v010)) + f.z * (gf.y * (v101 - v001) + f.y * (v111 - v011)),
                       gf.z * (gf.x * (v010 - v000) + f.x * (v110 - v100)) + f.z * (gf.x * (v011 - v001) + f.x * (v111 - v101)),
                       gf.y * (gf.x * (v001 - v000) + f.x * (v101 - v100)) + f.y * (gf.x * (v011 - v010) + f.x * (v111 - v110)));
  float inside = grids[g].quantum.x * value + offset;
  vec3 outside = x - p;
  float gap = length(outside);
  if (gap > 0.0) return LayerSample(gap + max(inside, 0.0), outside / gap);
  float len = length(gradient);
  return LayerSample(inside, len > 0.0 ? gradient / len : vec3(1.0, 0.0, 0.0));
}

LayerSample evaluate_layer(uint k, vec3 x) {
  uvec4 shape = layers[k].shape;
  if (shape.w != 0u) return evaluate_grid(shape.w - 1u, layers[k].grid.x, x);
  bool intersection = shape.z == 1u;
  LayerSample best = LayerSample(intersection ? -1e30 : 1e30, vec3(1.0, 0.0, 0.0));
  for (uint i = 0; i < shape.y; ++i) {
    LayerSample s = evaluate_primitive(primitives[shape.x + i], x);
    if (intersection ? s.phi > best.phi : s.phi < best.phi) best = s;
  }
  return best;
}

// Specialization constants: engine/ultrasound/ultrasound_pass.cpp makes a pipeline for each value
// an image needs. Lavapipe (Mesa 22.3) runs both sides of every branch under a mask and a loop's
// body at least once, and reads a uniform block lane by lane, with a bounds check, wherever the
// offset comes from a loop counter that is not a constant (gallivm's emit_load_ubo); with these
// constant the loops unroll, their uniforms are read once for all lanes, and an image of a tissue
// at rest has no Kelvinlet in it (docs/BENCHMARKS.md, "Third round").
layout(constant_id = 0) const uint LOADS = 0u;        // the tissue's loads (echo.loads), 0 at rest
layout(constant_id = 1) const int AXIAL_RADIUS = 0;   // the point spread function's, samples
layout(constant_id = 2) const int LATERAL_RADIUS = 0; // lines

// The rest position whose displaced position is x (echo_model.hpp, kRestIterations steps).
vec3 rest_position(vec3 x) {
  vec3 rest = x;
  if (LOADS == 0u) return rest;
  for (int i = 0; i < 4; ++i) {
    vec3 u = vec3(0.0);
    mat3 unused = mat3(0.0);
    for (uint k = 0; k < LOADS; ++k) add_kelvinlet(echo.loads[k], rest, echo.material.x, echo.material.y, false, u, unused);
    rest = x - u;
  }
  return rest;
}

// The nodes of a line (rest_offsets): from sample 0 to the first at or past the last sample.
uint rest_nodes() { return (echo.counts.y - 1u) / echo.kernel.w + 2u; }

// Sample j's rest position on `line`, x its position: the nodes' offsets linearly interpolated
// (engine/ultrasound/echo_model.hpp, rest_node_spacing, chooses their spacing for the error); at
// rest (LOADS 0) x itself, no image read.
vec3 rest_of_sample(uint line, uint j, vec3 x) {
  if (LOADS == 0u) return x;
  uint n = j / echo.kernel.w;
  float f = float(j - n * echo.kernel.w) / float(echo.kernel.w);
  return x + mix(imageLoad(rest_offsets, ivec2(n, line)).xyz, imageLoad(rest_offsets, ivec2(n + 1u, line)).xyz, f);
}

float axial_weight(int k) { return echo.axial_weights[k / 4][k % 4]; }
float lateral_weight(int k) { return echo.lateral_weights[k / 4][k % 4]; }
