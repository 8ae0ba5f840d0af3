// Builds tinygltf::Model objects in memory: one buffer, one bufferView per attribute.
#pragma once

#include <tiny_gltf.h>

#include <glm/glm.hpp>
#include <string>

#include "asset-gen/shapes.hpp"

namespace needle::asset_gen {

// Appends `bytes` to buffer 0 (created if needed) as a 4-byte-aligned bufferView and adds an
// accessor of `count` elements over it; returns the accessor's index.
int append_accessor(tinygltf::Model& model, const void* data, size_t bytes, size_t count, int type, int component_type,
                    int target = 0);

class GltfBuilder {
 public:
  // bin_uri: the external buffer's file name (e.g. "sphere_100.bin").
  explicit GltfBuilder(const std::string& bin_uri);

  // PBR metallic-roughness material; returns its index.
  int add_material(const std::string& name, const glm::vec4& base_color, float metallic, float roughness,
                   int base_color_texture = -1);
  // RGBA8 texture written next to the glTF as a PNG named `uri`; returns the texture index.
  int add_texture(const std::string& uri, int width, int height, std::vector<unsigned char> rgba8);
  // Mesh with one primitive (u16 indices while they fit, else u32); returns the mesh index.
  int add_mesh(const std::string& name, const MeshData& mesh, int material);
  // Root node of the default scene holding `mesh`, translated by `translation`.
  void add_root_node(const std::string& name, int mesh, const glm::dvec3& translation = glm::dvec3(0.0));

  const tinygltf::Model& model() const { return model_; }
  tinygltf::Model take() { return std::move(model_); }

 private:
  tinygltf::Model model_;
};

}  // namespace needle::asset_gen
