#version 450
#extension GL_GOOGLE_include_directive : require
#include "frame.glsl"
// The section's caps, first draw (engine/passes/section_caps.hpp): every face of a cut surface
// that lies on the kept side of the plane inverts the structure's stencil bit, so a pixel's bit
// ends set where the plane, seen through it, lies inside the structure. No colour.

layout(location = 0) in vec3 in_world_position;
// mesh.vert's other outputs, declared so that its interface matches.
layout(location = 1) in vec3 in_world_normal;
layout(location = 2) in vec2 in_uv;
layout(location = 3) in vec4 in_color;
layout(location = 4) flat in int in_sectioned;

void main() {
  if (dot(frame.section_plane.xyz, in_world_position) + frame.section_plane.w > 0.0) discard;
}
