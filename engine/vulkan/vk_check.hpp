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

}  // namespace needle::engine

#define VK_CHECK(call) ::needle::engine::vk_check((call), #call)
