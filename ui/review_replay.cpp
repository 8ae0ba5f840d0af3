#include "ui/review_replay.hpp"

#include <cmath>
#include <glm/glm.hpp>

namespace needle::ui {

void frame_beside_panels(engine::Camera& camera, float aspect, float left_fraction) {
  const glm::vec3 forward = camera.target - camera.position;
  const float distance = glm::length(forward);
  const glm::vec3 right = glm::normalize(glm::cross(forward, camera.up));
  const float visible = 1.0f - left_fraction;
  // Back off so the old view's width fits in the visible part; then slide the camera left by the
  // visible part's centre, NDC x = left_fraction, at the target's distance.
  const glm::vec3 backed = camera.target - forward / visible;
  const float half_width = (distance / visible) * aspect * std::tan(glm::radians(camera.fov_y_deg) * 0.5f);
  const glm::vec3 shift = -right * (left_fraction * half_width);
  camera.position = backed + shift;
  camera.target += shift;
}

}  // namespace needle::ui
