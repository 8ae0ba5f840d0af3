#version 450
// The ultrasound image's grey, linearly interpolated between lines and samples. The image holds
// display values and the target takes them as they are (a UNORM target holding sRGB-encoded
// values, docs/RENDERING.md, "Colour"), so the screen shows the image's own bytes.
layout(set = 0, binding = 0) uniform sampler2D image;
layout(location = 0) in vec4 in_uv;  // xy: across the lines, down the depth (viewport_quad.vert)
layout(location = 0) out vec4 out_color;

void main() {
  out_color = vec4(vec3(texture(image, in_uv.xy).r), 1.0);
}
