#version 450
// Cells: one work item a sample finds the layer holding it at its rest position (the tissue's
// displacement undone) and the scatterer of its cell there: a fixed random phasor, so the speckle
// stays put while the probe does and moves with the tissue. The scan lines (ultrasound_scan.comp)
// then walk these in order.
#extension GL_GOOGLE_include_directive : require
#include "ultrasound.glsl"

layout(local_size_x = 64) in;

// A PCG-style integer hash: the same cell always gives the same bits.
uint hash(uvec3 v) {
  uint h = v.x * 747796405u + v.y * 2891336453u + v.z * 1181783497u;
  h ^= h >> 16; h *= 2246822519u; h ^= h >> 13; h *= 3266489917u; h ^= h >> 16;
  return h;
}

// The scatterer of the cell holding rest position x: a unit phasor scaled by 1/sqrt(density), or none.
vec2 scatterer(vec3 x, float density) {
  uint h = hash(uvec3(ivec3(floor(x / echo.display.w))));
  if (float(h & 0xffffu) / 65536.0 >= density) return vec2(0.0);
  float phase = 6.283185307 * float(h >> 16) / 65536.0;
  return vec2(cos(phase), sin(phase)) / sqrt(density);
}

void main() {
  uint item = gl_GlobalInvocationID.x;
  uint samples = echo.counts.y;
  if (item >= echo.counts.x * samples) return;
  uint line = item / samples, j = item % samples;
  vec3 rest = rest_position(line_origin(line) + sample_depth(j) * echo.direction.xyz);
  int layer = layer_at(rest);
  cell_layers[item] = layer;
  echoes[item] = layer < 0 ? vec2(0.0) : echo.kernel.z == 1u ? scatterer(rest, layers[layer].material.w) : vec2(1.0, 0.0);
}
