// The GPU tissue deformation pass: a compute dispatch that rewrites the deformed positions and
// normals of tissue primitives in their vertex buffers from the rest mesh and this frame's
// DeformationField, visiting only the vertices the field (or last frame's) can reach. The graphics
// pass then reads the vertex buffers after a barrier: no CPU round trip. No change in the field,
// no dispatch.
#pragma once

#include <vulkan/vulkan.h>

#include <array>
#include <functional>
#include <vector>

#include "engine/deformation/deformation_field.hpp"
#include "engine/deformation/vertex_grid.hpp"
#include "engine/passes/gpu_model.hpp"
#include "engine/vulkan/gpu_buffer.hpp"

namespace needle::engine {

class VulkanContext;

class DeformationPass {
 public:
  static constexpr size_t kMaxLoads = 8;  // shaders/deform.comp MAX_LOADS
  static constexpr size_t kMaxRanges = 16384;

  explicit DeformationPass(const VulkanContext& context);
  ~DeformationPass();
  DeformationPass(const DeformationPass&) = delete;
  DeformationPass& operator=(const DeformationPass&) = delete;

  // A primitive to deform. Its vertices must already be in `grid`'s order (sort_vertices before
  // upload); `rest` is that sorted CPU copy. model_to_world must be a rotation, a translation and
  // a uniform scale (the field is isotropic); std::invalid_argument otherwise.
  void add_target(const GpuPrimitive& gpu, const Primitive& rest, VertexGrid grid, const glm::dmat4& model_to_world);

  // This frame's recorder for FrameParams::before_pass; empty when the field is the one already
  // applied. With every_vertex, all vertices are processed (tests of the unculled pass).
  std::function<void(VkCommandBuffer)> update(const DeformationField& field, bool every_vertex = false);

  struct FrameStats {
    size_t processed = 0;
    size_t skipped = 0;
    bool dispatched = false;
  };
  // What the last recorded frame did.
  const FrameStats& last_frame() const { return stats_; }

 private:
  static constexpr size_t kRing = 3;  // more than the renderer's frames in flight
  struct Target {
    VkBuffer vertices = VK_NULL_HANDLE;
    uint32_t vertex_count = 0;
    GpuBuffer rest;
    VertexGrid grid;
    glm::dmat4 world_to_model{1.0};
    double scale = 1.0;
    std::array<GpuBuffer, kRing> uniforms;
    std::array<GpuBuffer, kRing> ranges;
    VkDescriptorPool pool = VK_NULL_HANDLE;
    std::array<VkDescriptorSet, kRing> sets{};
    std::vector<Sphere> applied_support;  // model space, of the field last applied
  };
  struct PendingTarget {
    std::vector<uint8_t> uniforms;
    std::vector<uint32_t> ranges;  // (first vertex, first item) pairs
    uint32_t items = 0;
    std::vector<Sphere> support;
  };

  PendingTarget prepare(const Target& target, const DeformationField& field, bool every_vertex) const;
  void record(VkCommandBuffer cmd, const std::vector<PendingTarget>& pending, const DeformationField& field);

  const VulkanContext& context_;
  VkDevice device_;
  VkDescriptorSetLayout set_layout_ = VK_NULL_HANDLE;
  VkPipelineLayout pipeline_layout_ = VK_NULL_HANDLE;
  VkPipeline pipeline_ = VK_NULL_HANDLE;
  std::vector<Target> targets_;
  size_t ring_ = 0;
  DeformationField applied_;  // the field the vertex buffers hold
  FrameStats stats_;
};

}  // namespace needle::engine
