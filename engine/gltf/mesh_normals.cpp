#include "engine/gltf/mesh_normals.hpp"

namespace needle::engine {

void generate_normals(std::vector<MeshVertex>& vertices, const std::vector<uint32_t>& indices) {
  std::vector<glm::dvec3> sums(vertices.size(), glm::dvec3(0.0));
  for (size_t t = 0; t + 2 < indices.size(); t += 3) {
    const glm::dvec3 a(vertices[indices[t]].position);
    const glm::dvec3 b(vertices[indices[t + 1]].position);
    const glm::dvec3 c(vertices[indices[t + 2]].position);
    // |(b-a) x (c-a)| is twice the triangle's area: the weight comes for free.
    const glm::dvec3 n = glm::cross(b - a, c - a);
    for (size_t k = 0; k < 3; ++k) sums[indices[t + k]] += n;
  }
  for (size_t v = 0; v < vertices.size(); ++v) {
    const double length = glm::length(sums[v]);
    vertices[v].normal = length > 0.0 ? glm::vec3(sums[v] / length) : glm::vec3(0.0f, 0.0f, 1.0f);
  }
}

}  // namespace needle::engine
