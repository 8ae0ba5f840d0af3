#version 450
// The point spread function along the beam: each sample's complex echo convolved with the
// pulse's Gaussian envelope over the line's samples (the in-phase and quadrature parts alike).
#extension GL_GOOGLE_include_directive : require
#include "ultrasound.glsl"

layout(local_size_x = 64) in;

void main() {
  uint samples = echo.counts.y;
  if (gl_GlobalInvocationID.x >= samples) return;
  int j = int(gl_GlobalInvocationID.x), line = int(gl_WorkGroupID.y);
  int radius = int(echo.kernel.x);
  vec2 sum = imageLoad(echoes, ivec2(j, line)).xy * axial_weight(0);
  for (int k = 1; k <= radius; ++k) {
    float w = axial_weight(k);
    if (j - k >= 0) sum += w * imageLoad(echoes, ivec2(j - k, line)).xy;
    if (j + k < int(samples)) sum += w * imageLoad(echoes, ivec2(j + k, line)).xy;
  }
  imageStore(axial, ivec2(j, line), vec4(sum, 0.0, 0.0));
}
