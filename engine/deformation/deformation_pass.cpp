#include "engine/deformation/deformation_pass.hpp"

#include <cstring>
#include <memory>
#include <stdexcept>

#include "engine/vulkan/pipelines.hpp"
#include "engine/vulkan/vk_check.hpp"
#include "engine/vulkan/vulkan_context.hpp"
#include "spirv/deform_comp.h"

namespace needle::engine {
namespace {

constexpr uint32_t kWorkgroup = 64;  // local_size_x of deform.comp

// std140 mirror of deform.comp's Field block.
struct LoadUniform {
  glm::vec4 center_epsilon;
  glm::vec4 force_support;
};
struct FieldUniforms {
  glm::vec4 material;
  glm::uvec4 counts;
  LoadUniform loads[DeformationPass::kMaxLoads];
};
static_assert(sizeof(FieldUniforms) == 32 + 32 * DeformationPass::kMaxLoads, "std140 layout of Field");

// Uniform scale of a similarity transform; throws when the transform shears or scales unevenly.
double similarity_scale(const glm::dmat4& m) {
  glm::dmat3 l(m);
  double s = glm::length(l[0]);
  const double tol = 1e-6 * s;
  bool similar = s > 0.0 && std::abs(glm::length(l[1]) - s) < tol && std::abs(glm::length(l[2]) - s) < tol &&
                 std::abs(glm::dot(l[0], l[1])) < tol * s && std::abs(glm::dot(l[1], l[2])) < tol * s &&
                 std::abs(glm::dot(l[0], l[2])) < tol * s;
  if (!similar) {
    throw std::invalid_argument(
        "a deformable tissue's transform must be a rotation, a translation and a uniform scale");
  }
  return s;
}

}  // namespace

DeformationPass::DeformationPass(const VulkanContext& context) : context_(context), device_(context.device()) {
  set_layout_ = descriptor_set_layout(
      device_, {
                   {0, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 1, VK_SHADER_STAGE_COMPUTE_BIT, nullptr},
                   {1, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, VK_SHADER_STAGE_COMPUTE_BIT, nullptr},
                   {2, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, VK_SHADER_STAGE_COMPUTE_BIT, nullptr},
                   {3, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, VK_SHADER_STAGE_COMPUTE_BIT, nullptr},
               });
  pipeline_layout_ = single_set_pipeline_layout(device_, set_layout_);
  pipeline_ = compute_pipeline(device_, pipeline_layout_, deform_comp_spv, sizeof(deform_comp_spv));
}

DeformationPass::~DeformationPass() {
  for (Target& t : targets_) {
    if (t.pool) vkDestroyDescriptorPool(device_, t.pool, nullptr);
  }
  if (pipeline_) vkDestroyPipeline(device_, pipeline_, nullptr);
  if (pipeline_layout_) vkDestroyPipelineLayout(device_, pipeline_layout_, nullptr);
  if (set_layout_) vkDestroyDescriptorSetLayout(device_, set_layout_, nullptr);
}

void DeformationPass::add_target(const GpuPrimitive& gpu, const Primitive& rest, VertexGrid grid,
                                 const glm::dmat4& model_to_world) {
  if (rest.vertices.size() != gpu.vertex_count || grid.vertex_count() != gpu.vertex_count) {
    throw std::invalid_argument("deformation target: rest mesh, grid and GPU primitive disagree on the vertex count");
  }
  Target t;
  t.scale = similarity_scale(model_to_world);
  t.world_to_model = glm::inverse(model_to_world);
  t.vertices = gpu.vertices.handle();
  t.vertex_count = gpu.vertex_count;
  t.grid = std::move(grid);
  std::vector<float> rest_data;
  rest_data.reserve(rest.vertices.size() * 6);
  for (const MeshVertex& v : rest.vertices) {
    rest_data.insert(rest_data.end(), {v.position.x, v.position.y, v.position.z, v.normal.x, v.normal.y, v.normal.z});
  }
  t.rest = GpuBuffer::device_local_with_data(context_, rest_data.data(), rest_data.size() * sizeof(float),
                                             VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);

  std::array<VkDescriptorPoolSize, 2> sizes{
      {{VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, kRing}, {VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 3 * kRing}}};
  VkDescriptorPoolCreateInfo pool_info{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
  pool_info.maxSets = kRing;
  pool_info.poolSizeCount = uint32_t(sizes.size());
  pool_info.pPoolSizes = sizes.data();
  VK_CHECK(vkCreateDescriptorPool(device_, &pool_info, nullptr, &t.pool));
  for (size_t slot = 0; slot < kRing; ++slot) {
    t.uniforms[slot] = GpuBuffer::host_visible(context_, sizeof(FieldUniforms), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT);
    t.ranges[slot] =
        GpuBuffer::host_visible(context_, kMaxRanges * 2 * sizeof(uint32_t), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
    VkDescriptorSetAllocateInfo alloc{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
    alloc.descriptorPool = t.pool;
    alloc.descriptorSetCount = 1;
    alloc.pSetLayouts = &set_layout_;
    VK_CHECK(vkAllocateDescriptorSets(device_, &alloc, &t.sets[slot]));
    std::array<VkDescriptorBufferInfo, 4> buffers{{{t.uniforms[slot].handle(), 0, VK_WHOLE_SIZE},
                                                   {t.rest.handle(), 0, VK_WHOLE_SIZE},
                                                   {t.vertices, 0, VK_WHOLE_SIZE},
                                                   {t.ranges[slot].handle(), 0, VK_WHOLE_SIZE}}};
    std::array<VkWriteDescriptorSet, 4> writes{};
    for (uint32_t b = 0; b < 4; ++b) {
      writes[b] = {VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
      writes[b].dstSet = t.sets[slot];
      writes[b].dstBinding = b;
      writes[b].descriptorCount = 1;
      writes[b].descriptorType = b == 0 ? VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER : VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
      writes[b].pBufferInfo = &buffers[b];
    }
    vkUpdateDescriptorSets(device_, uint32_t(writes.size()), writes.data(), 0, nullptr);
  }
  targets_.push_back(std::move(t));
}

DeformationPass::PendingTarget DeformationPass::prepare(const Target& t, const DeformationField& field,
                                                        bool every_vertex) const {
  if (field.loads.size() > kMaxLoads) {
    throw std::invalid_argument("deformation field has " + std::to_string(field.loads.size()) +
                                " loads; the pass takes " + std::to_string(kMaxLoads));
  }
  PendingTarget p;
  FieldUniforms u{};
  u.material = glm::vec4(float(field.material.a()), float(field.material.b()), 0.0f, 0.0f);
  // The field in model coordinates (x_w = s R x_m + t): centres map back, lengths shrink by s,
  // and K(s R r; ε) f = R K(r; ε/s) Rᵀ f / s, so the model-space force is Rᵀ f / s = W f with
  // W = (s R)⁻¹ = the linear part of world_to_model.
  const glm::dmat3 w(t.world_to_model);
  for (size_t i = 0; i < field.loads.size(); ++i) {
    const Kelvinlet& k = field.loads[i];
    glm::dvec3 c = glm::dvec3(t.world_to_model * glm::dvec4(k.center, 1.0));
    glm::dvec3 f = w * k.force;
    u.loads[i] = {glm::vec4(glm::vec3(c), float(k.epsilon / t.scale)),
                  glm::vec4(glm::vec3(f), float(k.support / t.scale))};
    p.support.push_back({c, k.support / t.scale});
  }
  std::vector<VertexRange> ranges;
  if (every_vertex) {
    ranges.push_back({0, t.vertex_count});
  } else {
    std::vector<Sphere> reach = p.support;
    reach.insert(reach.end(), t.applied_support.begin(), t.applied_support.end());  // to put back to rest
    ranges = t.grid.ranges_near(reach);
    if (ranges.size() > kMaxRanges)
      ranges = {{ranges.front().first, ranges.back().first + ranges.back().count - ranges.front().first}};
  }
  for (const VertexRange& r : ranges) {
    p.ranges.insert(p.ranges.end(), {r.first, p.items});
    p.items += r.count;
  }
  u.counts = glm::uvec4(uint32_t(field.loads.size()), uint32_t(ranges.size()), p.items, 0u);
  p.uniforms.resize(sizeof u);
  std::memcpy(p.uniforms.data(), &u, sizeof u);
  return p;
}

std::function<void(VkCommandBuffer)> DeformationPass::update(const DeformationField& field, bool every_vertex) {
  if (!every_vertex && field == applied_) {
    stats_ = {0, 0, false};
    for (const Target& t : targets_) stats_.skipped += t.vertex_count;
    return {};
  }
  auto pending = std::make_shared<std::vector<PendingTarget>>();
  for (const Target& t : targets_) pending->push_back(prepare(t, field, every_vertex));
  return [this, pending, field](VkCommandBuffer cmd) { record(cmd, *pending, field); };
}

void DeformationPass::record(VkCommandBuffer cmd, const std::vector<PendingTarget>& pending,
                             const DeformationField& field) {
  const size_t slot = ring_;
  ring_ = (ring_ + 1) % kRing;
  stats_ = {0, 0, false};
  for (size_t i = 0; i < targets_.size(); ++i) {
    stats_.processed += pending[i].items;
    stats_.skipped += targets_[i].vertex_count - pending[i].items;
  }
  if (stats_.processed > 0) {
    // Earlier frames' vertex reads and this pass's earlier writes come before these writes.
    VkMemoryBarrier before{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
    before.srcAccessMask = VK_ACCESS_SHADER_WRITE_BIT;
    before.dstAccessMask = VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT;
    vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_VERTEX_INPUT_BIT | VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT,
                         VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, 0, 1, &before, 0, nullptr, 0, nullptr);
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline_);
    for (size_t i = 0; i < targets_.size(); ++i) {
      const PendingTarget& p = pending[i];
      if (p.items == 0) continue;
      Target& t = targets_[i];
      std::memcpy(t.uniforms[slot].mapped(), p.uniforms.data(), p.uniforms.size());
      std::memcpy(t.ranges[slot].mapped(), p.ranges.data(), p.ranges.size() * sizeof(uint32_t));
      vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline_layout_, 0, 1, &t.sets[slot], 0, nullptr);
      vkCmdDispatch(cmd, (p.items + kWorkgroup - 1) / kWorkgroup, 1, 1);
    }
    // The graphics pass reads the new positions and normals as vertex attributes.
    VkMemoryBarrier after{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
    after.srcAccessMask = VK_ACCESS_SHADER_WRITE_BIT;
    after.dstAccessMask = VK_ACCESS_VERTEX_ATTRIBUTE_READ_BIT;
    vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_PIPELINE_STAGE_VERTEX_INPUT_BIT, 0, 1, &after, 0,
                         nullptr, 0, nullptr);
    stats_.dispatched = true;
  }
  applied_ = field;
  for (size_t i = 0; i < targets_.size(); ++i) targets_[i].applied_support = pending[i].support;
}

}  // namespace needle::engine
