#version 450
#extension GL_GOOGLE_include_directive : require
#include "frame.glsl"

layout(set = 1, binding = 0) uniform sampler2D base_color_texture;

layout(location = 0) in vec3 in_world_position;
layout(location = 1) in vec3 in_world_normal;
layout(location = 2) in vec2 in_uv;
layout(location = 3) in vec4 in_color;
layout(location = 4) flat in int in_sectioned;

layout(location = 0) out vec4 out_color;

// The target is UNORM and holds sRGB-encoded values (docs/RENDERING.md, "Colour"): shading is in
// linear light, encoded here once per fragment rather than by the device on every write and blend.
vec3 srgb_encode(vec3 linear) {
  return mix(linear * 12.92, 1.055 * pow(linear, vec3(1.0 / 2.4)) - 0.055, greaterThan(linear, vec3(0.0031308)));
}

// Specialized per draw (scene_pass.cpp, "pipeline_index"): a CPU device (llvmpipe) runs both
// sides of every branch with the lanes masked, so code a draw cannot need is compiled out. Without
// discards it also writes depth before shading, not after (Mesa's lp_state_fs.c).
layout(constant_id = 0) const bool kMayDiscard = true;  // false: opaque, unmasked, unsectioned
layout(constant_id = 1) const bool kTextured = true;    // false: no base colour texture

// Blinn-Phong with the metallic-roughness parameters mapped onto it: enough shading for a
// trainee to judge depth and curvature, cheap enough for lavapipe at 1280x720.
void main() {
  vec4 base = material.base_color * in_color;
  if (kTextured && material.params.w > 0.5) base *= texture(base_color_texture, in_uv);  // sRGB decoded by the sampler
  if (kMayDiscard && material.params.x >= 0.0 && base.a < material.params.x) discard;

  vec3 n = normalize(in_world_normal);
  if (!gl_FrontFacing) n = -n;  // double-sided materials light their back faces too
  // The section view (docs/RENDERING.md). Cut: what lies beyond the plane is discarded (the caps
  // are drawn after, engine/passes/section_caps.hpp). Screen door: a fixed 4x4 ordered dither
  // keeps 5 fragments of 16 (no sorting, the needle shows through).
  if (kMayDiscard && in_sectioned != 0 && frame.section.x == 1) {
    if (dot(frame.section_plane.xyz, in_world_position) + frame.section_plane.w > 0.0) discard;
  } else if (kMayDiscard && in_sectioned != 0 && frame.section.x == 2) {
    const float bayer[16] = float[16](0.0, 8.0, 2.0, 10.0, 12.0, 4.0, 14.0, 6.0, 3.0, 11.0, 1.0, 9.0, 15.0, 7.0, 13.0, 5.0);
    ivec2 p = ivec2(gl_FragCoord.xy) & 3;
    if ((bayer[p.y * 4 + p.x] + 0.5) / 16.0 > 0.34) discard;
  }
  vec3 v = normalize(frame.camera_position.xyz - in_world_position);
  float metallic = clamp(material.params.y, 0.0, 1.0);
  float roughness = clamp(material.params.z, 0.04, 1.0);
  float shininess = 2.0 / (roughness * roughness * roughness * roughness) - 2.0;
  vec3 specular_color = mix(vec3(0.04), base.rgb, metallic);
  vec3 diffuse_color = base.rgb * (1.0 - metallic);

  vec3 color = frame.ambient.rgb * base.rgb;
  for (int i = 0; i < frame.light_count.x; ++i) {
    vec3 l = -frame.light_direction[i].xyz;
    float n_dot_l = max(dot(n, l), 0.0);
    if (n_dot_l <= 0.0) continue;
    vec3 h = normalize(l + v);
    // Normalized Blinn-Phong so rough surfaces do not glow.
    float spec = pow(max(dot(n, h), 0.0), shininess) * (shininess + 8.0) / 25.1327;
    color += frame.light_radiance[i].rgb * n_dot_l * (diffuse_color + specular_color * spec);
  }
  out_color = vec4(srgb_encode(max(color, vec3(0.0))), base.a);
}
