#include "app/patient_look.hpp"

#include <map>

namespace needle::app {

LayerLook patient_layer_look(const std::string& layer) {
  const glm::vec4 ligament{0.86f, 0.84f, 0.74f, 1.0f}, bone{0.93f, 0.91f, 0.83f, 1.0f};
  static const std::map<std::string, LayerLook> looks{
      {"skin", {{0.93f, 0.76f, 0.66f, 1.0f}, 0.6f, 2}},
      {"subcutaneous fat", {{0.98f, 0.88f, 0.55f, 1.0f}, 0.5f, 2}},
      {"erector spinae", {{0.72f, 0.30f, 0.28f, 1.0f}, 0.55f, 2}},
      {"supraspinous ligament", {ligament, 0.45f, 1}},
      {"interspinous ligament", {ligament * 0.9f + glm::vec4(0, 0, 0, 0.1f), 0.45f, 1}},
      {"ligamentum flavum", {{0.95f, 0.82f, 0.35f, 1.0f}, 0.4f, 1}},
      {"epidural space", {{0.99f, 0.93f, 0.70f, 1.0f}, 0.5f, 1}},
      {"dura", {{0.70f, 0.78f, 0.92f, 1.0f}, 0.35f, 1}},
      {"cerebrospinal fluid", {{0.55f, 0.75f, 0.95f, 1.0f}, 0.2f, 1}},
      {"intervertebral disc", {{0.78f, 0.84f, 0.88f, 1.0f}, 0.5f, 1}},
      {"bone", {bone, 0.7f, 1}},
      {"iliac crest", {bone, 0.7f, 2}}};
  const auto it = looks.find(layer);
  return it != looks.end() ? it->second : LayerLook{};
}

}  // namespace needle::app
