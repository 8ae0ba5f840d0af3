#include "engine/deformation/needle_pose.hpp"

#define GLM_ENABLE_EXPERIMENTAL
#include <glm/gtx/quaternion.hpp>  // glm::rotation: the shortest arc between two vectors

namespace needle::engine {

glm::mat4 needle_pose(const glm::dvec3& tip, const glm::dvec3& axis) {
  glm::dquat q = glm::rotation(glm::dvec3(1.0, 0.0, 0.0), glm::normalize(axis));
  glm::dmat4 m = glm::mat4_cast(q);
  m[3] = glm::dvec4(tip, 1.0);
  return glm::mat4(m);
}

}  // namespace needle::engine
