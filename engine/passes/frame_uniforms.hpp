// C++ mirror of shaders/frame.glsl (std140 uniform block and the push-constant block).
#pragma once

#include <glm/glm.hpp>

namespace needle::engine {

constexpr int kMaxDirectionalLights = 4;

struct FrameUniforms {
  glm::mat4 view_proj;
  glm::vec4 camera_position;
  glm::vec4 ambient;
  glm::vec4 light_direction[kMaxDirectionalLights];
  glm::vec4 light_radiance[kMaxDirectionalLights];
  glm::ivec4 light_count;
  glm::vec4 section_plane;  // xyz the unit normal, w its offset: n·x + w > 0 is cut away
  glm::ivec4 section;       // x: 0 none, 1 cut, 2 translucent
};
static_assert(sizeof(FrameUniforms) == 64 + 16 + 16 + 64 + 64 + 16 + 32, "std140 layout of Frame");

struct DrawPushConstants {
  glm::mat4 model;
  glm::vec4 normal_matrix[3];  // std430 mat3's three columns; the first's w: 1 when the section cuts this draw
};
static_assert(sizeof(DrawPushConstants) == 112, "push-constant layout of Draw (at most 128)");

struct MaterialUniforms {
  glm::vec4 base_color;
  glm::vec4 params;  // alpha cutoff (<0: none), metallic, roughness, has texture
};
static_assert(sizeof(MaterialUniforms) == 32, "std140 layout of MaterialBlock");

}  // namespace needle::engine
