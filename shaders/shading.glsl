// The scene's surface shading, shared by mesh.frag and mesh_translucent.frag (after frame.glsl
// and their inputs in_uv and in_color): the material's base colour and Blinn-Phong with the
// metallic-roughness parameters mapped onto it, enough shading for a trainee to judge depth and
// curvature, cheap enough for lavapipe at 1280x720.

layout(set = 1, binding = 0) uniform sampler2D base_color_texture;

// Specialized per draw (engine/passes/mesh_pipelines.hpp): a CPU device (llvmpipe) runs both
// sides of every branch with the lanes masked, so code a draw cannot need is compiled out.
layout(constant_id = 1) const bool kTextured = true;  // false: no base colour texture

// The target is UNORM and holds sRGB-encoded values (docs/RENDERING.md, "Colour"): shading is in
// linear light, encoded once per fragment rather than by the device on every write and blend.
vec3 srgb_encode(vec3 linear) {
  return mix(linear * 12.92, 1.055 * pow(linear, vec3(1.0 / 2.4)) - 0.055, greaterThan(linear, vec3(0.0031308)));
}

// The material's factor times the vertex colour and, if any, the texture (sRGB decoded by the sampler).
vec4 base_color() {
  vec4 base = material.base_color * in_color;
  if (kTextured && material.params.w > 0.5) base *= texture(base_color_texture, in_uv);
  return base;
}

// Specular anti-aliasing (Tokuyoshi and Kaplanyan, "Improved Geometric Specular Antialiasing",
// I3D 2019, as Filament's normal filtering): how much the normal `n` turns within the pixel, as a
// roughness² to add, min(2 σ² (|∂n/∂x|² + |∂n/∂y|²), 0.2) with Filament's σ² = 0.15 and
// threshold 0.2. Without it a thin metal shaft (the needle: 0.8 mm radius, roughness 0.25, a
// lobe of 3° on a normal that turns 30° or more a pixel) lights only the pixels whose centres
// fall in its highlight, a dotted streak that crawls as the needle moves. Call before any
// discard: the derivatives need the whole 2x2 quad.
float normal_roughness2(vec3 n) {
  vec3 dx = dFdx(n), dy = dFdy(n);
  return min(2.0 * 0.15 * (dot(dx, dx) + dot(dy, dy)), 0.2);
}

// Linear light leaving a surface of colour `base` with unit normal `n` at `world_position`
// towards the camera: ambient, then per light n·l (diffuse + normalized Blinn-Phong specular,
// its lobe widened by `added_roughness2`, normal_roughness2's).
vec3 lit(vec3 base, vec3 n, vec3 world_position, float added_roughness2) {
  vec3 v = normalize(frame.camera_position.xyz - world_position);
  float metallic = clamp(material.params.y, 0.0, 1.0);
  float roughness = clamp(material.params.z, 0.04, 1.0);
  // Blinn-Phong's exponent for a GGX roughness² α² = roughness⁴: 2 / α² − 2.
  float alpha2 = clamp(roughness * roughness * roughness * roughness + added_roughness2, 0.0, 1.0);
  float shininess = 2.0 / alpha2 - 2.0;
  vec3 specular_color = mix(vec3(0.04), base, metallic);
  vec3 diffuse_color = base * (1.0 - metallic);

  vec3 color = frame.ambient.rgb * base;
  for (int i = 0; i < frame.light_count.x; ++i) {
    vec3 l = -frame.light_direction[i].xyz;
    float n_dot_l = max(dot(n, l), 0.0);
    if (n_dot_l <= 0.0) continue;
    vec3 h = normalize(l + v);
    // Normalized Blinn-Phong so rough surfaces do not glow.
    float spec = pow(max(dot(n, h), 0.0), shininess) * (shininess + 8.0) / 25.1327;
    color += frame.light_radiance[i].rgb * n_dot_l * (diffuse_color + specular_color * spec);
  }
  return max(color, vec3(0.0));
}
