// A Model uploaded to the GPU: vertex and index buffers per primitive, textures, and one
// material descriptor set per material. Vertex buffers are also storage buffers, so a compute
// pass may rewrite them in place (tissue deformation), and transfer sources, so tests can read them.
#pragma once

#include <vulkan/vulkan.h>

#include <vector>

#include "engine/model.hpp"
#include "engine/passes/triangle_chunks.hpp"
#include "engine/vulkan/gpu_buffer.hpp"
#include "engine/vulkan/gpu_image.hpp"

namespace needle::engine {

class VulkanContext;

// What a GpuModel needs from the renderer to build its material descriptor sets.
struct MaterialBinding {
  // set 1: combined image sampler at binding 0, MaterialUniforms at binding 1
  VkDescriptorSetLayout layout = VK_NULL_HANDLE;
  VkSampler sampler = VK_NULL_HANDLE;
  VkImageView white_texture = VK_NULL_HANDLE;  // bound when a material has no texture
};

// One triangle list of a primitive's index buffer: the full mesh or a coarser level of detail.
struct GpuLevel {
  uint32_t first_index = 0;
  uint32_t index_count = 0;
  std::vector<TriangleChunk> chunks;  // of the uploaded (rest) mesh, first_index counted from the buffer's start
};

struct GpuPrimitive {
  GpuBuffer vertices;
  GpuBuffer indices;  // the full mesh's, then each coarser level's
  uint32_t vertex_count = 0;
  uint32_t index_count = 0;      // of the full mesh
  std::vector<GpuLevel> levels;  // the full mesh, then Primitive::coarser_indices
  Sphere bounds;                 // of the rest vertices, model space: how big the mesh looks, to choose a level
  Bounds box;                    // of the rest vertices, model space
};

// Uploads one primitive's vertices and indices to device-local buffers.
GpuPrimitive upload_primitive(const VulkanContext& context, const Primitive& primitive);
// Copies a primitive's vertex buffer back to the host after compute or transfer writes, and waits.
std::vector<MeshVertex> read_back_vertices(const VulkanContext& context, const GpuPrimitive& primitive);

class GpuModel {
 public:
  GpuModel(const VulkanContext& context, const Model& model, const MaterialBinding& binding);
  ~GpuModel();
  GpuModel(const GpuModel&) = delete;
  GpuModel& operator=(const GpuModel&) = delete;

  const std::vector<GpuPrimitive>& primitives() const { return primitives_; }
  const std::vector<MeshInstance>& instances() const { return instances_; }
  const Bounds& world_bounds() const { return bounds_; }
  // The material of a primitive (the glTF default material when it has none) and its set.
  const Material& material_of(uint32_t primitive) const;
  VkDescriptorSet descriptor_set_of(uint32_t primitive) const;

 private:
  VkDevice device_;
  std::vector<GpuPrimitive> primitives_;
  std::vector<int> primitive_material_;
  std::vector<MeshInstance> instances_;
  std::vector<Material> materials_;  // the model's, then the default material last
  std::vector<GpuImage> textures_;
  GpuBuffer material_uniforms_;  // one aligned MaterialUniforms slice per entry of materials_
  VkDescriptorPool pool_ = VK_NULL_HANDLE;
  std::vector<VkDescriptorSet> sets_;  // one per entry of materials_
  Bounds bounds_;
};

}  // namespace needle::engine
