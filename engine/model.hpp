// CPU-side renderable model: what the glTF loader produces and the renderer uploads.
// Everything is already validated, triangulated and flattened to world space per instance.
#pragma once

#include <cstdint>
#include <glm/glm.hpp>
#include <stdexcept>
#include <string>
#include <vector>

namespace needle::engine {

// A fault in an asset or scene file. what() reads "FILE: ELEMENT: what is wrong",
// e.g. "sphere.gltf: accessors[3]: byteOffset 64 + 12 x 100 exceeds bufferView length 800".
struct AssetError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

struct MeshVertex {
  glm::vec3 position{0.0f};
  glm::vec3 normal{0.0f, 0.0f, 1.0f};
  glm::vec2 uv{0.0f};
  glm::vec4 color{1.0f};  // COLOR_0 (linear), white when absent
};

// 8-bit RGBA texels as stored in the image file (sRGB-encoded for base colour).
struct Texture {
  uint32_t width = 0;
  uint32_t height = 0;
  std::vector<uint8_t> rgba8;
};

enum class AlphaMode { Opaque, Mask, Blend };

struct Material {
  glm::vec4 base_color_factor{1.0f};
  int base_color_texture = -1;  // index into Model::textures, -1 when none
  float metallic_factor = 1.0f;
  float roughness_factor = 1.0f;
  AlphaMode alpha_mode = AlphaMode::Opaque;
  float alpha_cutoff = 0.5f;
  bool double_sided = false;
};

// One triangle list. Normals are always present (generated when the file had none).
struct Primitive {
  std::vector<MeshVertex> vertices;
  std::vector<uint32_t> indices;
  // Coarser triangle lists over the same vertices, finest first: the asset's levels of detail,
  // drawn when the mesh covers few pixels (a deformation still moves every vertex).
  std::vector<std::vector<uint32_t>> coarser_indices;
  int material = -1;  // index into Model::materials, -1 for the glTF default material
};

// A primitive placed in the world by its node's accumulated transform.
struct MeshInstance {
  uint32_t primitive = 0;
  glm::mat4 world{1.0f};
  std::string node_name;
};

struct Bounds {
  glm::vec3 min{0.0f};
  glm::vec3 max{0.0f};
  bool empty() const { return min.x > max.x; }
};

// A ball: a mesh's bounds, or where a deformation reaches.
struct Sphere {
  glm::dvec3 center{0.0};
  double radius = 0.0;
};

struct Model {
  std::vector<Primitive> primitives;
  std::vector<Material> materials;
  std::vector<Texture> textures;
  std::vector<MeshInstance> instances;
  Bounds world_bounds;  // of every instance's transformed vertices
};

}  // namespace needle::engine
