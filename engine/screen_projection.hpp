// Where the scene renderer puts a world point on the screen: its camera's GL-style perspective
// (depth 0 to 1) and a viewport that flips y, so world up is screen up. The UI uses it to draw
// guidance over the 3D view.
#pragma once

#include <glm/glm.hpp>
#include <optional>

#include "engine/extent.hpp"
#include "engine/scene.hpp"

namespace needle::engine {

glm::mat4 view_projection(const Camera& camera, Extent extent);

// Pixel coordinates with the origin at the top left; nullopt for a point behind the camera.
std::optional<glm::vec2> project_to_screen(const Camera& camera, Extent extent, const glm::vec3& world);

}  // namespace needle::engine
