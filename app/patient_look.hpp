// How a generated patient's layers look when drawn (linear RGB, roughness, the mesh's stride on the
// lattice), by layer name: the skin of the back, yellow fat, red muscle, pale ligaments, the
// flavum's yellow, bone's ivory; the same colours as the lumbar section's (tools/asset-gen).
#pragma once

#include <glm/glm.hpp>
#include <string>

namespace needle::app {

struct LayerLook {
  glm::vec4 color{1.0f};
  float roughness = 0.5f;
  int stride = 1;  // mesh every stride-th node: 2 for the large smooth regions, 1 for bone and ligaments
};

LayerLook patient_layer_look(const std::string& layer);

}  // namespace needle::app
