#version 450
#extension GL_GOOGLE_include_directive : require
#include "frame.glsl"

layout(location = 0) in vec3 in_position;
layout(location = 1) in vec3 in_normal;
layout(location = 2) in vec2 in_uv;
layout(location = 3) in vec4 in_color;

layout(location = 0) out vec3 out_world_position;
layout(location = 1) out vec3 out_world_normal;
layout(location = 2) out vec2 out_uv;
layout(location = 3) out vec4 out_color;
layout(location = 4) flat out int out_sectioned;

void main() {
  vec4 world = draw.model * vec4(in_position, 1.0);
  out_world_position = world.xyz;
  out_world_normal = mat3(draw.normal_columns[0].xyz, draw.normal_columns[1].xyz, draw.normal_columns[2].xyz) * in_normal;
  out_sectioned = draw.normal_columns[0].w > 0.5 ? 1 : 0;
  out_uv = in_uv;
  out_color = in_color;
  gl_Position = frame.view_proj * world;
}
