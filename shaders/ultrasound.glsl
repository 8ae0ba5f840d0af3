// What the three ultrasound passes share (engine/ultrasound/ultrasound_pass.cpp mirrors it, std140
// and std430): the frame's probe, needle and display settings, and the buffers between the passes.
// The model: docs/RENDERING.md, "Ultrasound"; its double-precision reference:
// engine/ultrasound/echo_model.cpp.
#include "kelvinlet.glsl"

#define MAX_LOADS 8
#define KERNEL_VEC4S 5  // up to 17 weights (radius 16) of the point spread function, 4 to a vec4

layout(set = 0, binding = 0, std140) uniform Echo {
  vec4 origin;       // xyz: the probe face's centre
  vec4 direction;    // xyz: the beams' direction
  vec4 lateral;      // xyz: along the array
  vec4 elevation;    // xyz: direction × lateral
  vec4 image;        // x depth, y width, z sample spacing, w line spacing (m)
  uvec4 counts;      // x lines, y samples, z layers, w loads
  uvec4 kernel;      // x axial radius (samples), y lateral radius (lines), z speckle (0/1)
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

// The scene's layers, outside in, and their primitives (engine/ultrasound.hpp, EchoLayer).
struct Layer {
  uvec4 shape;    // x first primitive, y count, z 1 intersection / 0 union
  vec4 material;  // x impedance (MRayl), y attenuation (dB/(cm MHz)), z echogenicity, w scatterer density
};
struct Primitive {
  vec4 a_kind;    // xyz a, w kind: 0 sphere, 1 plane, 2 capsule
  vec4 b_radius;  // xyz b, w radius
};
layout(set = 0, binding = 1, std430) readonly buffer Layers {
  Layer layers[16];
  Primitive primitives[128];
};

// The received echo per sample, complex (in-phase, quadrature), line after line; after the axial
// convolution; and what each scan line met (engine/ultrasound.hpp, ScanLine).
layout(set = 0, binding = 2, std430) buffer Echoes { vec2 echoes[]; };
layout(set = 0, binding = 3, std430) buffer Axial { vec2 axial[]; };
#define MAX_INTERFACES 24
struct Interface {
  float depth;
  int from_layer;
  int to_layer;
  float pad;
};
struct LineRecord {
  uint count;
  float shadow_depth;   // −1: none
  float needle_depth;
  float needle_weight;  // 0: the line misses the needle
  Interface interfaces[MAX_INTERFACES];
};
layout(set = 0, binding = 4, std430) buffer Lines { LineRecord lines[]; };
layout(set = 0, binding = 5, rgba8) uniform writeonly image2D picture;

float axial_weight(int k) { return echo.axial_weights[k / 4][k % 4]; }
float lateral_weight(int k) { return echo.lateral_weights[k / 4][k % 4]; }
