#version 450
// One quad filling the viewport (the ultrasound image's rectangle on the screen, the render
// scale's whole target): two triangles from the vertex index, no vertex buffer.
//
// The coordinate leaves as a vec4 read back as `.xy`: llvmpipe takes its linear path for a
// textured rectangle (upscale.frag) only when the texture coordinate is built from the input's
// components, not when it is a whole vec2 input (Mesa's lp_state_fs_analysis.c); measured, the
// upscale 1.7 ms against 3.5 to 4.0 ms on the general path (docs/BENCHMARKS.md).
layout(location = 0) out vec4 out_uv;

void main() {
  const vec2 corners[6] = vec2[6](vec2(0, 0), vec2(1, 0), vec2(0, 1), vec2(1, 0), vec2(1, 1), vec2(0, 1));
  vec2 c = corners[gl_VertexIndex];
  out_uv = vec4(c, 0.0, 1.0);  // from the top left: u across, v down
  gl_Position = vec4(2.0 * c - 1.0, 0.0, 1.0);  // Vulkan's y points down: v = 0 at the top
}
