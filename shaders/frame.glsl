// Per-frame uniforms shared by the scene shaders; mirrored by engine/passes/frame_uniforms.hpp (std140).
#define MAX_DIRECTIONAL_LIGHTS 4
layout(set = 0, binding = 0, std140) uniform Frame {
  mat4 view_proj;
  vec4 camera_position;                          // xyz, world
  vec4 ambient;                                  // rgb, linear
  vec4 light_direction[MAX_DIRECTIONAL_LIGHTS];  // xyz: the way light travels, unit
  vec4 light_radiance[MAX_DIRECTIONAL_LIGHTS];   // rgb: colour x intensity
  ivec4 light_count;                             // x
  vec4 section_plane;                            // xyz unit normal, w offset: n.x + w > 0 is cut away
  ivec4 section;                                 // x: 0 none, 1 cut, 2 translucent
} frame;

// Per draw: object-to-world transform and its inverse-transpose for normals (computed once on
// the CPU rather than per vertex: llvmpipe shades vertices on one thread).
layout(push_constant, std430) uniform Draw {
  mat4 model;
  vec4 normal_columns[3];  // the normal matrix's columns; normal_columns[0].w: 1 when the section cuts this draw
} draw;

// Per material (set 1): base colour texture and factors; mirrored by engine/passes/frame_uniforms.hpp.
layout(set = 1, binding = 1, std140) uniform MaterialBlock {
  vec4 base_color;
  vec4 params;  // x alpha cutoff (<0: no cutoff), y metallic, z roughness, w has texture (0/1)
} material;
