#include "engine/vulkan/gpu_buffer.hpp"

#include <cstring>
#include <string>
#include <utility>

#include "engine/vulkan/vk_check.hpp"
#include "engine/vulkan/vulkan_context.hpp"

namespace needle::engine {

GpuBuffer::GpuBuffer(const VulkanContext& context, VkDeviceSize size, VkBufferUsageFlags usage,
                     VkMemoryPropertyFlags memory)
    : device_(context.device()), size_(size) {
  VkBufferCreateInfo info{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
  info.size = size;
  info.usage = usage;
  info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
  const std::string what = "a " + std::to_string(size >> 20) + " MiB buffer", device = context.device_description();
  vk_check_size(vkCreateBuffer(device_, &info, nullptr, &buffer_), "vkCreateBuffer", what, device);
  VkMemoryRequirements req;
  vkGetBufferMemoryRequirements(device_, buffer_, &req);
  VkMemoryAllocateInfo alloc{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
  alloc.allocationSize = req.size;
  alloc.memoryTypeIndex = context.memory_type(req.memoryTypeBits, memory);
  try {
    vk_check_size(vkAllocateMemory(device_, &alloc, nullptr, &memory_), "vkAllocateMemory", what, device);
    vk_check_size(vkBindBufferMemory(device_, buffer_, memory_, 0), "vkBindBufferMemory", what, device);
    if (memory & VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT)
      VK_CHECK(vkMapMemory(device_, memory_, 0, VK_WHOLE_SIZE, 0, &mapped_));
  } catch (...) {
    reset();
    throw;
  }
}

GpuBuffer::~GpuBuffer() { reset(); }

GpuBuffer::GpuBuffer(GpuBuffer&& other) noexcept { *this = std::move(other); }

GpuBuffer& GpuBuffer::operator=(GpuBuffer&& other) noexcept {
  if (this != &other) {
    reset();
    device_ = std::exchange(other.device_, VK_NULL_HANDLE);
    buffer_ = std::exchange(other.buffer_, VK_NULL_HANDLE);
    memory_ = std::exchange(other.memory_, VK_NULL_HANDLE);
    size_ = std::exchange(other.size_, 0);
    mapped_ = std::exchange(other.mapped_, nullptr);
  }
  return *this;
}

void GpuBuffer::reset() {
  if (!device_) return;
  if (buffer_) vkDestroyBuffer(device_, buffer_, nullptr);
  if (memory_) vkFreeMemory(device_, memory_, nullptr);  // unmaps implicitly
  buffer_ = VK_NULL_HANDLE;
  memory_ = VK_NULL_HANDLE;
  mapped_ = nullptr;
  device_ = VK_NULL_HANDLE;
}

GpuBuffer GpuBuffer::host_visible(const VulkanContext& context, VkDeviceSize size, VkBufferUsageFlags usage) {
  return GpuBuffer(context, size, usage, VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT);
}

GpuBuffer GpuBuffer::device_local_with_data(const VulkanContext& context, const void* data, VkDeviceSize size,
                                            VkBufferUsageFlags usage) {
  GpuBuffer staging = host_visible(context, size, VK_BUFFER_USAGE_TRANSFER_SRC_BIT);
  std::memcpy(staging.mapped(), data, size);
  GpuBuffer buffer(context, size, usage | VK_BUFFER_USAGE_TRANSFER_DST_BIT, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
  context.submit_and_wait([&](VkCommandBuffer cmd) {
    VkBufferCopy region{0, 0, size};
    vkCmdCopyBuffer(cmd, staging.handle(), buffer.handle(), 1, &region);
  });
  return buffer;
}

}  // namespace needle::engine
