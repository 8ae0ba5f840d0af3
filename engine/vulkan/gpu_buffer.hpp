// Owned VkBuffer + VkDeviceMemory. Host-visible buffers stay mapped for their lifetime.
#pragma once

#include <vulkan/vulkan.h>

#include <cstddef>

namespace needle::engine {

class VulkanContext;

class GpuBuffer {
 public:
  GpuBuffer() = default;
  GpuBuffer(const VulkanContext& context, VkDeviceSize size, VkBufferUsageFlags usage, VkMemoryPropertyFlags memory);
  ~GpuBuffer();
  GpuBuffer(GpuBuffer&& other) noexcept;
  GpuBuffer& operator=(GpuBuffer&& other) noexcept;
  GpuBuffer(const GpuBuffer&) = delete;
  GpuBuffer& operator=(const GpuBuffer&) = delete;

  VkBuffer handle() const { return buffer_; }
  VkDeviceSize size() const { return size_; }
  // Non-null only for host-visible buffers (kept coherent: we ask for HOST_COHERENT).
  void* mapped() const { return mapped_; }

  // A device-local buffer filled from host memory through a staging buffer.
  static GpuBuffer device_local_with_data(const VulkanContext& context, const void* data, VkDeviceSize size,
                                          VkBufferUsageFlags usage);
  // A host-visible, coherent, mapped buffer.
  static GpuBuffer host_visible(const VulkanContext& context, VkDeviceSize size, VkBufferUsageFlags usage);

 private:
  void reset();
  VkDevice device_ = VK_NULL_HANDLE;
  VkBuffer buffer_ = VK_NULL_HANDLE;
  VkDeviceMemory memory_ = VK_NULL_HANDLE;
  VkDeviceSize size_ = 0;
  void* mapped_ = nullptr;
};

}  // namespace needle::engine
