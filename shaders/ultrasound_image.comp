#version 450
// The point spread function across the lines, the envelope (the complex echo's magnitude) and log
// compression: grey = 1 + (20 log10(envelope) + gain) / dynamic range, clamped to [0, 1]. The
// picture is the image as shown: line i is column i, sample j row j. A work item does one sample
// of LINES_PER_ITEM neighbouring lines.
#extension GL_GOOGLE_include_directive : require
#include "ultrasound.glsl"

layout(local_size_x = 64) in;

void main() {
  uint samples = echo.counts.y;
  int line_count = int(echo.counts.x);
  uint j = gl_GlobalInvocationID.x;
  if (j >= samples) return;
  const int radius = LATERAL_RADIUS;
  int first = int(gl_WorkGroupID.y) * LINES_PER_ITEM;
  for (int line = first; line < min(first + LINES_PER_ITEM, line_count); ++line) {
    vec2 sum = imageLoad(axial, ivec2(j, line)).xy * lateral_weight(0);
    for (int m = 1; m <= radius; ++m) {
      float w = lateral_weight(m);
      if (line - m >= 0) sum += w * imageLoad(axial, ivec2(j, line - m)).xy;
      if (line + m < line_count) sum += w * imageLoad(axial, ivec2(j, line + m)).xy;
    }
    float decibels = 20.0 * log(max(length(sum), 1e-12)) / log(10.0);
    float grey = clamp(1.0 + (decibels + echo.display.y) / echo.display.x, 0.0, 1.0);
    imageStore(picture, ivec2(line, int(j)), vec4(grey, grey, grey, 1.0));
  }
}
