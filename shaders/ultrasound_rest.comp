#version 450
// Rest positions, for a deformed tissue only: one work item a node of a line (ultrasound.glsl,
// rest_offsets) undoes the tissue's displacement there, for ultrasound_echoes.comp to interpolate
// between the nodes instead of undoing it at every sample. The lines are the SIMD lanes, so a
// node's loads are read once for them all.
#extension GL_GOOGLE_include_directive : require
#include "ultrasound.glsl"

layout(local_size_x = 64) in;

void main() {
  uint line = gl_GlobalInvocationID.x, node = gl_GlobalInvocationID.y;
  if (line >= echo.counts.x || node >= rest_nodes()) return;
  vec3 x = line_origin(line) + sample_depth(node * echo.kernel.w) * echo.direction.xyz;
  imageStore(rest_offsets, ivec2(node, line), vec4(rest_position(x) - x, 0.0));
}
