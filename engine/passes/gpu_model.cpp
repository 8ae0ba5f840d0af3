#include "engine/passes/gpu_model.hpp"

#include <array>
#include <cstring>

#include "engine/passes/frame_uniforms.hpp"
#include "engine/vulkan/vk_check.hpp"
#include "engine/vulkan/vulkan_context.hpp"

namespace needle::engine {
namespace {

// Chunks are also cut where the normals turn (triangle_chunks.hpp); this bounds the flat ones,
// so that a flat mesh still culls in pieces and a chunk's sphere stays small.
constexpr uint32_t kTrianglesPerChunk = 256;

}  // namespace

GpuPrimitive upload_primitive(const VulkanContext& context, const Primitive& p) {
  GpuPrimitive gpu;
  gpu.vertex_count = static_cast<uint32_t>(p.vertices.size());
  gpu.index_count = static_cast<uint32_t>(p.indices.size());
  if (gpu.vertex_count == 0 || gpu.index_count == 0) return gpu;
  gpu.vertices = GpuBuffer::device_local_with_data(
      context, p.vertices.data(), p.vertices.size() * sizeof(MeshVertex),
      VK_BUFFER_USAGE_VERTEX_BUFFER_BIT | VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_SRC_BIT);
  std::vector<const std::vector<uint32_t>*> lists{&p.indices};
  for (const auto& coarser : p.coarser_indices) lists.push_back(&coarser);
  std::vector<uint32_t> all;
  for (const std::vector<uint32_t>* list : lists) {
    GpuLevel level{uint32_t(all.size()), uint32_t(list->size()),
                   build_triangle_chunks(p.vertices, *list, kTrianglesPerChunk)};
    for (TriangleChunk& chunk : level.chunks) chunk.first_index += level.first_index;
    gpu.levels.push_back(std::move(level));
    all.insert(all.end(), list->begin(), list->end());
  }
  glm::vec3 lo(p.vertices[0].position), hi = lo;
  for (const MeshVertex& v : p.vertices) lo = glm::min(lo, v.position), hi = glm::max(hi, v.position);
  gpu.bounds = {glm::dvec3((lo + hi) * 0.5f), double(glm::length(hi - lo) * 0.5f)};
  gpu.box = {lo, hi};
  gpu.indices = GpuBuffer::device_local_with_data(context, all.data(), all.size() * sizeof(uint32_t),
                                                  VK_BUFFER_USAGE_INDEX_BUFFER_BIT);
  return gpu;
}

std::vector<MeshVertex> read_back_vertices(const VulkanContext& context, const GpuPrimitive& gpu) {
  GpuBuffer host =
      GpuBuffer::host_visible(context, gpu.vertex_count * sizeof(MeshVertex), VK_BUFFER_USAGE_TRANSFER_DST_BIT);
  context.submit_and_wait([&](VkCommandBuffer cmd) {
    VkMemoryBarrier barrier{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
    barrier.srcAccessMask = VK_ACCESS_SHADER_WRITE_BIT | VK_ACCESS_TRANSFER_WRITE_BIT;
    barrier.dstAccessMask = VK_ACCESS_TRANSFER_READ_BIT;
    vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_TRANSFER_BIT,
                         VK_PIPELINE_STAGE_TRANSFER_BIT, 0, 1, &barrier, 0, nullptr, 0, nullptr);
    VkBufferCopy region{0, 0, host.size()};
    vkCmdCopyBuffer(cmd, gpu.vertices.handle(), host.handle(), 1, &region);
    VkMemoryBarrier to_host{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
    to_host.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
    to_host.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
    vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0, 1, &to_host, 0, nullptr, 0,
                         nullptr);
  });
  std::vector<MeshVertex> out(gpu.vertex_count);
  std::memcpy(out.data(), host.mapped(), host.size());
  return out;
}

GpuModel::GpuModel(const VulkanContext& context, const Model& model, const MaterialBinding& binding)
    : device_(context.device()), instances_(model.instances), materials_(model.materials), bounds_(model.world_bounds) {
  materials_.push_back(Material{});  // glTF's default material, for primitives without one
  for (const Primitive& p : model.primitives) {
    primitives_.push_back(upload_primitive(context, p));
    primitive_material_.push_back(p.material >= 0 ? p.material : int(materials_.size()) - 1);
  }
  for (const Texture& t : model.textures) textures_.push_back(GpuImage::texture(context, t));

  const VkDeviceSize align = context.properties().limits.minUniformBufferOffsetAlignment;
  const VkDeviceSize stride = (sizeof(MaterialUniforms) + align - 1) / align * align;
  std::vector<uint8_t> uniforms(stride * materials_.size());
  for (size_t i = 0; i < materials_.size(); ++i) {
    const Material& m = materials_[i];
    MaterialUniforms u{m.base_color_factor,
                       glm::vec4(m.alpha_mode == AlphaMode::Mask ? m.alpha_cutoff : -1.0f, m.metallic_factor,
                                 m.roughness_factor, m.base_color_texture >= 0 ? 1.0f : 0.0f)};
    if (m.alpha_mode == AlphaMode::Opaque) u.base_color.a = 1.0f;
    std::memcpy(uniforms.data() + i * stride, &u, sizeof u);
  }
  material_uniforms_ =
      GpuBuffer::device_local_with_data(context, uniforms.data(), uniforms.size(), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT);

  std::array<VkDescriptorPoolSize, 2> sizes{{{VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, uint32_t(materials_.size())},
                                             {VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, uint32_t(materials_.size())}}};
  VkDescriptorPoolCreateInfo pool_info{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
  pool_info.maxSets = uint32_t(materials_.size());
  pool_info.poolSizeCount = uint32_t(sizes.size());
  pool_info.pPoolSizes = sizes.data();
  VK_CHECK(vkCreateDescriptorPool(device_, &pool_info, nullptr, &pool_));

  std::vector<VkDescriptorSetLayout> layouts(materials_.size(), binding.layout);
  VkDescriptorSetAllocateInfo alloc{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
  alloc.descriptorPool = pool_;
  alloc.descriptorSetCount = uint32_t(layouts.size());
  alloc.pSetLayouts = layouts.data();
  sets_.resize(layouts.size());
  VK_CHECK(vkAllocateDescriptorSets(device_, &alloc, sets_.data()));
  for (size_t i = 0; i < materials_.size(); ++i) {
    int t = materials_[i].base_color_texture;
    VkDescriptorImageInfo image{
        binding.sampler, t >= 0 && size_t(t) < textures_.size() ? textures_[size_t(t)].view() : binding.white_texture,
        VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
    VkDescriptorBufferInfo buffer{material_uniforms_.handle(), i * stride, sizeof(MaterialUniforms)};
    std::array<VkWriteDescriptorSet, 2> writes{};
    writes[0] = {VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
    writes[0].dstSet = sets_[i];
    writes[0].descriptorCount = 1;
    writes[0].descriptorType = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
    writes[0].pImageInfo = &image;
    writes[1] = writes[0];
    writes[1].dstBinding = 1;
    writes[1].descriptorType = VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER;
    writes[1].pImageInfo = nullptr;
    writes[1].pBufferInfo = &buffer;
    vkUpdateDescriptorSets(device_, uint32_t(writes.size()), writes.data(), 0, nullptr);
  }
}

GpuModel::~GpuModel() {
  if (pool_) vkDestroyDescriptorPool(device_, pool_, nullptr);
}

const Material& GpuModel::material_of(uint32_t primitive) const {
  return materials_[size_t(primitive_material_[primitive])];
}

VkDescriptorSet GpuModel::descriptor_set_of(uint32_t primitive) const {
  return sets_[size_t(primitive_material_[primitive])];
}

}  // namespace needle::engine
