#version 450
// The render scale's upscale (engine/passes/scaled_scene.hpp): the smaller scene, bilinear, over
// the whole target. The sample is written as it is, into a pass without depth, so llvmpipe fills
// the rectangle on its linear path (viewport_quad.vert says when).
layout(set = 0, binding = 0) uniform sampler2D scene;
layout(location = 0) in vec4 in_uv;  // xy (viewport_quad.vert)
layout(location = 0) out vec4 out_color;

void main() {
  out_color = texture(scene, in_uv.xy);
}
