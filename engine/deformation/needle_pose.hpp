// The needle asset's transform from the tool state: its origin is the tip and its +x axis the
// needle's (the thesis's x5), so the pose is a translation to the tip and the shortest rotation
// taking +x onto the axis.
#pragma once

#include <glm/glm.hpp>

namespace needle::engine {

glm::mat4 needle_pose(const glm::dvec3& tip, const glm::dvec3& axis);

}  // namespace needle::engine
