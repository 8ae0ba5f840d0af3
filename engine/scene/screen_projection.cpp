#include "engine/screen_projection.hpp"

#include <glm/gtc/matrix_transform.hpp>

namespace needle::engine {

glm::mat4 view_projection(const Camera& camera, Extent extent) {
  const float aspect = float(extent.width) / float(extent.height);
  return glm::perspective(glm::radians(camera.fov_y_deg), aspect, camera.near_m, camera.far_m) *
         glm::lookAt(camera.position, camera.target, camera.up);
}

std::optional<glm::vec2> project_to_screen(const Camera& camera, Extent extent, const glm::vec3& world) {
  const glm::vec4 clip = view_projection(camera, extent) * glm::vec4(world, 1.0f);
  if (clip.w <= 0.0f) return std::nullopt;
  const glm::vec2 ndc = glm::vec2(clip) / clip.w;
  return glm::vec2((ndc.x + 1.0f) * 0.5f * float(extent.width), (1.0f - ndc.y) * 0.5f * float(extent.height));
}

}  // namespace needle::engine
