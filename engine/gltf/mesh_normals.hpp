// Vertex normals for meshes that come without them.
#pragma once

#include <cstdint>
#include <vector>

#include "engine/model.hpp"

namespace needle::engine {

// Sets each vertex normal to the area-weighted mean of the normals of the triangles that use
// it (the sum of their unnormalized cross products, normalized). Vertices of degenerate
// triangles only get +z. Indices must already be validated (< vertices.size()).
void generate_normals(std::vector<MeshVertex>& vertices, const std::vector<uint32_t>& indices);

}  // namespace needle::engine
