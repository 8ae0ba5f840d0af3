// Vulkan result checking: a failed call becomes an exception naming the call and the result.
#pragma once

#include <vulkan/vulkan.h>

#include <stdexcept>
#include <string>

namespace needle::engine {

struct VulkanError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

const char* vk_result_name(VkResult result);

inline void vk_check(VkResult result, const char* call) {
  if (result != VK_SUCCESS) throw VulkanError(std::string(call) + " failed: " + vk_result_name(result));
}

// For the calls that make a resource: running out of memory means the resource `what` ("a
// 16384x16384 colour image, 4 samples per pixel (4096 MiB)") is too large for the device on
// `device`, said so; any other failure is vk_check's.
inline void vk_check_size(VkResult result, const char* call, const std::string& what, const std::string& device) {
  if (result == VK_ERROR_OUT_OF_DEVICE_MEMORY || result == VK_ERROR_OUT_OF_HOST_MEMORY)
    throw VulkanError(what + " is too large for this device (" + device + "): " + vk_result_name(result) + " from " +
                      call);
  vk_check(result, call);
}

}  // namespace needle::engine

#define VK_CHECK(call) ::needle::engine::vk_check((call), #call)
