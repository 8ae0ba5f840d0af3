// Shared set-up of the deformation tests: a thesis sphere on the GPU, spatially ordered, and
// the needle states of the thesis's experiments.
#pragma once

#include <cstring>

#include "asset-gen/assets.hpp"
#include "engine/deformation/deformation_pass.hpp"
#include "engine/gltf_loader.hpp"
#include "engine/vulkan/vulkan_context.hpp"

namespace needle::test {

constexpr glm::dvec3 kSphereCentre{0.4, 0.0, 0.0};
constexpr double kSphereRadius = 0.1;

struct GpuSphere {
  engine::Primitive rest;  // sorted by the grid, model space
  glm::dmat4 model_to_world{1.0};
  engine::GpuPrimitive gpu;
};

inline GpuSphere make_gpu_sphere(const engine::VulkanContext& context, int resolution,
                                 const glm::dmat4& extra = glm::dmat4(1.0), double cell_size = 0.01,
                                 engine::VertexGrid* grid_out = nullptr) {
  engine::Model model = engine::convert_gltf(asset_gen::make_sphere(resolution, resolution), "sphere");
  GpuSphere s;
  s.rest = model.primitives.at(0);
  s.model_to_world = extra * glm::dmat4(model.instances.at(0).world);
  engine::VertexGrid grid = engine::VertexGrid::sort_vertices(s.rest, cell_size);
  if (grid_out) *grid_out = grid;
  s.gpu = engine::upload_primitive(context, s.rest);
  return s;
}

// A needle touching (pushing a dimple) or inserted into the sphere, entering along the inward
// normal at the surface point in direction `dir`, pivoted by `pivot_rad` about its tip towards
// `towards` (made perpendicular to the normal), the tissue pushed that way by `lateral_N`.
inline engine::NeedleLoad sphere_load(engine::NeedleContact contact, const glm::dvec3& dir, double depth_m,
                                      double pivot_rad = 0.0, double lateral_N = 0.0,
                                      const glm::dvec3& towards = {0.0, 1.0, 0.0}) {
  engine::NeedleLoad load;
  load.contact = contact;
  glm::dvec3 n = glm::normalize(dir);
  load.surface_point = kSphereCentre + kSphereRadius * n;
  load.surface_normal = n;
  glm::dvec3 inward = -n;
  load.tip = load.surface_point + inward * depth_m;
  glm::dvec3 side = glm::normalize(towards - n * glm::dot(towards, n));
  load.axis = std::cos(pivot_rad) * inward + std::sin(pivot_rad) * side;
  load.lateral_force_on_tissue_N = side * lateral_N;
  return load;
}

// Fills the vertex buffer with NaN so that a vertex the pass should write and does not is seen.
inline void poison(const engine::VulkanContext& context, const engine::GpuPrimitive& gpu) {
  context.submit_and_wait([&](VkCommandBuffer cmd) {
    VkMemoryBarrier barrier{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
    barrier.srcAccessMask = VK_ACCESS_SHADER_WRITE_BIT | VK_ACCESS_TRANSFER_WRITE_BIT;
    barrier.dstAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
    vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_TRANSFER_BIT,
                         VK_PIPELINE_STAGE_TRANSFER_BIT, 0, 1, &barrier, 0, nullptr, 0, nullptr);
    vkCmdFillBuffer(cmd, gpu.vertices.handle(), 0, VK_WHOLE_SIZE, 0x7fc00000u);  // quiet NaN
    VkMemoryBarrier after{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
    after.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
    after.dstAccessMask = VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT | VK_ACCESS_TRANSFER_READ_BIT;
    vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT,
                         VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_TRANSFER_BIT, 0, 1, &after, 0,
                         nullptr, 0, nullptr);
  });
}

}  // namespace needle::test
