// The Vulkan instance, the chosen physical device, the logical device and its graphics queue.
// Device preference: discrete GPU, then integrated, then virtual, then a CPU device (lavapipe).
#pragma once

#include <vulkan/vulkan.h>

#include <functional>
#include <mutex>
#include <string>
#include <vector>

#include "engine/gpu_device.hpp"

namespace needle::engine {

class Window;

class VulkanContext {
 public:
  // With a window, the instance gets the extensions to present to it, the context its surface,
  // and the chosen device must present to that.
  explicit VulkanContext(const DeviceOptions& options, const Window* window = nullptr);
  ~VulkanContext();
  VulkanContext(const VulkanContext&) = delete;
  VulkanContext& operator=(const VulkanContext&) = delete;

  VkInstance instance() const { return instance_; }
  VkPhysicalDevice physical_device() const { return physical_device_; }
  VkDevice device() const { return device_; }
  VkQueue queue() const { return queue_; }
  uint32_t queue_family() const { return queue_family_; }
  VkSurfaceKHR surface() const { return surface_; }
  VkCommandPool command_pool() const { return command_pool_; }
  const VkPhysicalDeviceProperties& properties() const { return properties_; }
  std::string device_description() const;

  // Memory type index with the given bits among allowed_types; throws when there is none.
  uint32_t memory_type(uint32_t allowed_types, VkMemoryPropertyFlags flags) const;
  // Nanoseconds a timestamp tick lasts; 0 when the queue cannot write timestamps in both graphics
  // and compute work.
  double timestamp_period_ns() const;
  // The bits of a timestamp that count (the queue family's timestampValidBits).
  uint32_t timestamp_valid_bits() const { return timestamp_valid_bits_; }
  // VK_EXT_external_memory_host is enabled (a CPU device made for a window, when it offers it).
  bool imports_host_memory() const { return imports_host_memory_; }
  // shaderStorageImageExtendedFormats is enabled (when the device offers it).
  bool storage_image_extended_formats() const { return storage_image_extended_formats_; }
  // Highest sample count ≤ wanted supported for colour, depth and stencil attachments together.
  VkSampleCountFlagBits max_msaa(int wanted) const;

  // Records with `record` into a one-time command buffer, submits, and waits.
  void submit_and_wait(const std::function<void(VkCommandBuffer)>& record) const;

  // Every message the validation layer sent (warnings and errors), in order. Tests assert it is empty.
  std::vector<std::string> validation_messages() const;
  bool validation_enabled() const { return messenger_ != VK_NULL_HANDLE; }

 private:
  static VKAPI_ATTR VkBool32 VKAPI_CALL on_debug_message(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                                         VkDebugUtilsMessageTypeFlagsEXT type,
                                                         const VkDebugUtilsMessengerCallbackDataEXT* data, void* self);
  void create_instance(const DeviceOptions& options, const Window* window);
  void pick_physical_device();
  void create_device();
  void release();

  VkInstance instance_ = VK_NULL_HANDLE;
  VkDebugUtilsMessengerEXT messenger_ = VK_NULL_HANDLE;
  VkSurfaceKHR surface_ = VK_NULL_HANDLE;
  VkPhysicalDevice physical_device_ = VK_NULL_HANDLE;
  VkPhysicalDeviceProperties properties_{};
  VkPhysicalDeviceMemoryProperties memory_properties_{};
  VkDevice device_ = VK_NULL_HANDLE;
  VkQueue queue_ = VK_NULL_HANDLE;
  uint32_t queue_family_ = 0;
  uint32_t timestamp_valid_bits_ = 0;
  bool imports_host_memory_ = false;
  bool storage_image_extended_formats_ = false;
  VkCommandPool command_pool_ = VK_NULL_HANDLE;

  mutable std::mutex messages_mutex_;  // the layer may call back from the driver's threads
  std::vector<std::string> messages_;
};

}  // namespace needle::engine
