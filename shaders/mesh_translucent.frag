#version 450
#extension GL_GOOGLE_include_directive : require
#include "frame.glsl"
// The section's translucent tissue, weighted blended order-independent transparency (McGuire and
// Bavoil, JCGT 2(2), 2013; engine/passes/translucent_pass.hpp): each fragment adds its
// premultiplied colour, weighted by its depth, to the accumulation and its optical depth
// −ln(1 − alpha) to the revealage; translucent_composite.frag then lays their weighted mean over
// the opaque scene. No sorting, the same picture in any draw order.

layout(location = 0) in vec3 in_world_position;
layout(location = 1) in vec3 in_world_normal;
layout(location = 2) in vec2 in_uv;
layout(location = 3) in vec4 in_color;
layout(location = 4) flat in int in_sectioned;

layout(location = 0) out vec4 out_accumulation;
layout(location = 1) out float out_revealage;

#include "shading.glsl"

// A tissue surface's opacity: engine/passes/translucent_pass.hpp's kTranslucentAlpha.
layout(constant_id = 2) const float kAlpha = 0.25;

void main() {
  vec3 n = normalize(in_world_normal);
  if (!gl_FrontFacing) n = -n;
  vec3 color = srgb_encode(lit(base_color().rgb, n, in_world_position, normal_roughness2(n)));
  // The paper's equation (10): nearer fragments weigh more, so the nearest layer's colour leads.
  float z = gl_FragCoord.z;
  float weight = kAlpha * max(1e-2, 3e3 * (1.0 - z) * (1.0 - z) * (1.0 - z));
  out_accumulation = vec4(color * kAlpha, kAlpha) * weight;
  out_revealage = -log(1.0 - kAlpha);
}
