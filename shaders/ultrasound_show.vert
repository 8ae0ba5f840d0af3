#version 450
// The ultrasound image drawn as one quad filling the viewport (set to the image's rectangle on
// the screen): two triangles from the vertex index, no vertex buffer.
layout(location = 0) out vec2 out_uv;

void main() {
  const vec2 corners[6] = vec2[6](vec2(0, 0), vec2(1, 0), vec2(0, 1), vec2(1, 0), vec2(1, 1), vec2(0, 1));
  vec2 c = corners[gl_VertexIndex];
  out_uv = c;  // u across the lines, v down the depth
  gl_Position = vec4(2.0 * c - 1.0, 0.0, 1.0);  // Vulkan's y points down: v = 0 at the top
}
