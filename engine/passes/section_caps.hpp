// The section view's caps (docs/RENDERING.md, "Section view"): where the plane cuts a structure,
// its cut face filled with the structure's colour, exact where structures touch and share faces.
// Per structure, in the scene pass after the opaque meshes: every face of its kept side inverts
// a stencil bit (no colour, no depth test), so the bit is set exactly where the plane seen through
// the pixel lies inside the closed surface; then one quad in the plane, lit with the plane's
// normal, is drawn where the bit is set. Every structure's quad is the same quad, so their depths
// are the same bits: where two overlap (one inside the other) the later in the scene's order shows,
// and two that only touch never cover the same sample.
#pragma once

#include <vulkan/vulkan.h>

#include <array>
#include <cstdint>
#include <vector>

#include "engine/model.hpp"
#include "engine/passes/mesh_draws.hpp"
#include "engine/vulkan/gpu_buffer.hpp"

namespace needle::engine {

class MeshPipelines;
class VulkanContext;

// (section, bounding spheres of what it cuts, world space) => two counter-clockwise triangles of
// a square in the plane covering every sphere's cut, normals the plane's. Drawn with the depth
// test LESS_OR_EQUAL, a cap hides what lies behind the plane and nothing in front of it: a needle
// lying in the plane shows its near half whole, outline included.
std::array<MeshVertex, 6> cap_quad(const Section& section, const std::vector<Sphere>& cut);

class SectionCaps {
 public:
  // Pipelines for `render_pass` (the scene's) at `samples`; a quad buffer per frame slot.
  SectionCaps(const VulkanContext& context, const MeshPipelines& pipelines, VkRenderPass render_pass,
              VkSampleCountFlagBits samples, uint32_t slots);
  ~SectionCaps();
  SectionCaps(const SectionCaps&) = delete;
  SectionCaps& operator=(const SectionCaps&) = delete;

  // Records the caps of the sectioned draws among `draws` (a Cut section's) seen by `camera`,
  // inside the scene's render pass over `extent` with the frame's set bound; returns the
  // triangles drawn. Each structure's two draws are scissored to where its reach projects, so a
  // structure costs the pixels it covers, not the whole cut's.
  size_t record(VkCommandBuffer cmd, uint32_t slot, const std::vector<MeshDraw>& draws, const Section& section,
                const Camera& camera, VkExtent2D extent);

 private:
  VkDevice device_;
  VkPipelineLayout layout_;
  VkPipeline stencil_ = VK_NULL_HANDLE;
  std::array<VkPipeline, 2> caps_{};  // untextured, textured
  std::vector<GpuBuffer> quads_;      // per frame slot
};

}  // namespace needle::engine
