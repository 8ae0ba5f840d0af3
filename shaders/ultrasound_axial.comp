#version 450
// The point spread function along the beam: each sample's complex echo convolved with the
// pulse's Gaussian envelope over the line's samples (the in-phase and quadrature parts alike); a
// work item does one sample of LINES_PER_ITEM lines.
#extension GL_GOOGLE_include_directive : require
#include "ultrasound.glsl"

layout(local_size_x = 64) in;

void main() {
  int samples = int(echo.counts.y);
  int j = int(gl_GlobalInvocationID.x);
  if (j >= samples) return;
  const int radius = AXIAL_RADIUS;
  int first = int(gl_WorkGroupID.y) * LINES_PER_ITEM;
  for (int line = first; line < min(first + LINES_PER_ITEM, int(echo.counts.x)); ++line) {
    vec2 sum = imageLoad(echoes, ivec2(j, line)).xy * axial_weight(0);
    for (int k = 1; k <= radius; ++k) {
      float w = axial_weight(k);
      if (j - k >= 0) sum += w * imageLoad(echoes, ivec2(j - k, line)).xy;
      if (j + k < samples) sum += w * imageLoad(echoes, ivec2(j + k, line)).xy;
    }
    imageStore(axial, ivec2(j, line), vec4(sum, 0.0, 0.0));
  }
}
