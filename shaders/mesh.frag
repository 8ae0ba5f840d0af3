#version 450
#extension GL_GOOGLE_include_directive : require
#include "frame.glsl"

layout(set = 1, binding = 0) uniform sampler2D base_color_texture;

layout(location = 0) in vec3 in_world_position;
layout(location = 1) in vec3 in_world_normal;
layout(location = 2) in vec2 in_uv;
layout(location = 3) in vec4 in_color;

layout(location = 0) out vec4 out_color;

// Blinn-Phong with the metallic-roughness parameters mapped onto it: enough shading for a
// trainee to judge depth and curvature, cheap enough for lavapipe at 1280x720.
void main() {
  vec4 base = material.base_color * in_color;
  if (material.params.w > 0.5) base *= texture(base_color_texture, in_uv);  // sRGB decoded by the sampler
  if (material.params.x >= 0.0 && base.a < material.params.x) discard;

  vec3 n = normalize(in_world_normal);
  if (!gl_FrontFacing) n = -n;  // double-sided materials light their back faces too
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
  out_color = vec4(color, base.a);
}
