#version 450
// The ultrasound image's grey, linearly interpolated between lines and samples. The image holds
// display values; the target encodes linear to sRGB on write, so they are decoded first and the
// screen shows the image's own bytes.
layout(set = 0, binding = 0) uniform sampler2D image;
layout(location = 0) in vec2 in_uv;
layout(location = 0) out vec4 out_color;

void main() {
  float v = texture(image, in_uv).r;
  float linear = v <= 0.04045 ? v / 12.92 : pow((v + 0.055) / 1.055, 2.4);
  out_color = vec4(vec3(linear), 1.0);
}
