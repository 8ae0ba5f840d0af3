#version 450
// Echoes: one work item a sample (of LINES_PER_ITEM lines) adds the tissue's echo to the specular
// echoes the line pass left there (ultrasound_lines.comp): the round-trip amplitude of its run,
// attenuated to its depth
// and time-gain compensated, times its layer's backscatter on the scatterer of its cell at its
// rest position (a fixed random phasor, so the speckle stays put while the probe does and moves
// with the tissue; the rest position interpolated between ultrasound_rest.comp's nodes).
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

// Adds the tissue's echo to sample j of `line`.
void add_tissue_echo(uint line, uint j) {
  Run run = load_run(line, 0u);
  uint count = lines[line].run_count;
  for (uint k = 1u; k < count; ++k) {
    Run next = load_run(line, k);
    if (next.first <= j) run = next;
  }
  if (run.layer < 0) return;  // gel: the specular echoes alone
  float z = sample_depth(j);
  float gained = run.amplitude * exp(-2.0 * run.alpha * (z - interval_start(run.first))) * time_gain(z);
  vec2 scatter = vec2(1.0, 0.0);
  if (echo.kernel.z == 1u)
    scatter = scatterer(rest_of_sample(line, j, line_origin(line) + z * echo.direction.xyz), layers[run.layer].material.w);
  ivec2 at = ivec2(j, line);
  vec2 received = imageLoad(echoes, at).xy + gained * echo.beam.z * layers[run.layer].material.z * echo.display.z * scatter;
  imageStore(echoes, at, vec4(received, 0.0, 0.0));
}

// A work item's lines are the same for all the items of its group (gl_WorkGroupID.y), so what it
// reads of a line is the same for all its SIMD lanes: a CPU device (lavapipe) loads it once for them.
void main() {
  uint j = gl_GlobalInvocationID.x;
  if (j >= echo.counts.y) return;
  uint first = gl_WorkGroupID.y * LINES_PER_ITEM;
  for (uint line = first; line < min(first + LINES_PER_ITEM, echo.counts.x); ++line) add_tissue_echo(line, j);
}
