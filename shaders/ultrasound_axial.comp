#version 450
// The point spread function along the beam: each sample's complex echo convolved with the
// pulse's Gaussian envelope over the line's samples (the in-phase and quadrature parts alike).
#extension GL_GOOGLE_include_directive : require
#include "ultrasound.glsl"

layout(local_size_x = 64) in;

void main() {
  uint samples = echo.counts.y;
  if (gl_GlobalInvocationID.x >= samples) return;
  int j = int(gl_GlobalInvocationID.x);  // of line gl_WorkGroupID.y
  uint base = gl_WorkGroupID.y * samples;
  uint item = base + uint(j);
  int radius = int(echo.kernel.x);
  vec2 sum = echoes[item] * axial_weight(0);
  for (int k = 1; k <= radius; ++k) {
    float w = axial_weight(k);
    if (j - k >= 0) sum += w * echoes[base + uint(j - k)];
    if (j + k < int(samples)) sum += w * echoes[base + uint(j + k)];
  }
  axial[item] = sum;
}
