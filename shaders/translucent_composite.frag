#version 450
// The translucent tissue laid over the opaque scene (engine/passes/translucent_pass.hpp): the
// weighted mean of its fragments' colours, with the coverage 1 − Π (1 − alpha), blended over what
// is there. Texel for pixel: the accumulation images are the scene's size.
layout(set = 0, binding = 0) uniform sampler2D accumulation;
layout(set = 0, binding = 1) uniform sampler2D revealage;
layout(location = 0) in vec4 in_uv;  // viewport_quad.vert's; the pixel's own texel is read instead
layout(location = 0) out vec4 out_color;

void main() {
  ivec2 texel = ivec2(gl_FragCoord.xy);
  float depth = texelFetch(revealage, texel, 0).r;  // Σ −ln(1 − alpha)
  if (depth <= 0.0) discard;  // no translucent fragment here
  float reveal = exp(-depth);  // Π (1 − alpha)
  vec4 sum = texelFetch(accumulation, texel, 0);
  out_color = vec4(sum.rgb / max(sum.a, 1e-5), 1.0 - reveal);
}
