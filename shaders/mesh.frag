#version 450
#extension GL_GOOGLE_include_directive : require
#include "frame.glsl"

layout(location = 0) in vec3 in_world_position;
layout(location = 1) in vec3 in_world_normal;
layout(location = 2) in vec2 in_uv;
layout(location = 3) in vec4 in_color;
layout(location = 4) flat in int in_sectioned;

layout(location = 0) out vec4 out_color;

#include "shading.glsl"

// Specialized per draw, as kTextured: without discards llvmpipe also writes depth before
// shading, not after (Mesa's lp_state_fs.c).
layout(constant_id = 0) const bool kMayDiscard = true;  // false: opaque, unmasked, unsectioned

void main() {
  vec3 n = normalize(in_world_normal);
  if (!gl_FrontFacing) n = -n;  // double-sided materials light their back faces too
  float added_roughness2 = normal_roughness2(n);
  vec4 base = base_color();
  if (kMayDiscard && material.params.x >= 0.0 && base.a < material.params.x) discard;

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
  out_color = vec4(srgb_encode(lit(base.rgb, n, in_world_position, added_roughness2)), base.a);
}
