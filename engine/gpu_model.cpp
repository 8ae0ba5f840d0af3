#include "engine/gpu_model.hpp"

#include "engine/vk_check.hpp"
#include "engine/vulkan_context.hpp"

namespace needle::engine {

GpuModel::GpuModel(const VulkanContext& context, const Model& model, const MaterialBinding& binding)
    : device_(context.device()), instances_(model.instances), materials_(model.materials), bounds_(model.world_bounds) {
  materials_.push_back(Material{});  // glTF's default material, for primitives without one
  for (const Primitive& p : model.primitives) {
    GpuPrimitive gpu;
    gpu.vertex_count = static_cast<uint32_t>(p.vertices.size());
    gpu.index_count = static_cast<uint32_t>(p.indices.size());
    if (gpu.vertex_count && gpu.index_count) {
      gpu.vertices = GpuBuffer::device_local_with_data(context, p.vertices.data(), p.vertices.size() * sizeof(MeshVertex),
                                                       VK_BUFFER_USAGE_VERTEX_BUFFER_BIT | VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
      gpu.indices = GpuBuffer::device_local_with_data(context, p.indices.data(), p.indices.size() * sizeof(uint32_t),
                                                      VK_BUFFER_USAGE_INDEX_BUFFER_BIT);
    }
    primitives_.push_back(std::move(gpu));
    primitive_material_.push_back(p.material >= 0 ? p.material : int(materials_.size()) - 1);
  }
  for (const Texture& t : model.textures) textures_.push_back(GpuImage::texture(context, t));

  VkDescriptorPoolSize size{VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, uint32_t(materials_.size())};
  VkDescriptorPoolCreateInfo pool_info{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
  pool_info.maxSets = uint32_t(materials_.size());
  pool_info.poolSizeCount = 1;
  pool_info.pPoolSizes = &size;
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
    VkDescriptorImageInfo image{binding.sampler,
                                t >= 0 && size_t(t) < textures_.size() ? textures_[size_t(t)].view() : binding.white_texture,
                                VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
    VkWriteDescriptorSet write{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
    write.dstSet = sets_[i];
    write.descriptorCount = 1;
    write.descriptorType = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
    write.pImageInfo = &image;
    vkUpdateDescriptorSets(device_, 1, &write, 0, nullptr);
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
