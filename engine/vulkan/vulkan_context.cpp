#include "engine/vulkan/vulkan_context.hpp"

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <optional>
#include <string_view>

#include "engine/vulkan/vk_check.hpp"
#include "engine/vulkan/window_surface.hpp"

namespace needle::engine {
namespace {

constexpr const char* kValidationLayer = "VK_LAYER_KHRONOS_validation";

bool has_layer(const char* name) {
  uint32_t count = 0;
  vkEnumerateInstanceLayerProperties(&count, nullptr);
  std::vector<VkLayerProperties> layers(count);
  vkEnumerateInstanceLayerProperties(&count, layers.data());
  return std::any_of(layers.begin(), layers.end(), [&](const auto& l) { return std::strcmp(l.layerName, name) == 0; });
}

int type_rank(VkPhysicalDeviceType type) {
  switch (type) {
    case VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU:
      return 4;
    case VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU:
      return 3;
    case VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU:
      return 2;
    case VK_PHYSICAL_DEVICE_TYPE_CPU:
      return 1;
    default:
      return 0;
  }
}

const char* type_name(VkPhysicalDeviceType type) {
  switch (type) {
    case VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU:
      return "discrete GPU";
    case VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU:
      return "integrated GPU";
    case VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU:
      return "virtual GPU";
    case VK_PHYSICAL_DEVICE_TYPE_CPU:
      return "CPU";
    default:
      return "other";
  }
}

}  // namespace

VulkanContext::VulkanContext(const DeviceOptions& options, const Window* window) {
  create_instance(options, window);
  try {
    if (window) surface_ = create_window_surface(*window, instance_);
    pick_physical_device();
    create_device();
  } catch (...) {
    release();  // the destructor does not run when the constructor throws
    throw;
  }
  if (options.announce_device) std::printf("Vulkan device: %s\n", device_description().c_str());
}

VulkanContext::~VulkanContext() { release(); }

void VulkanContext::release() {
  if (device_) {
    vkDeviceWaitIdle(device_);
    if (command_pool_) vkDestroyCommandPool(device_, command_pool_, nullptr);
    vkDestroyDevice(device_, nullptr);
    device_ = VK_NULL_HANDLE;
  }
  if (surface_) vkDestroySurfaceKHR(instance_, surface_, nullptr);
  surface_ = VK_NULL_HANDLE;
  if (messenger_) {
    auto destroy = reinterpret_cast<PFN_vkDestroyDebugUtilsMessengerEXT>(
        vkGetInstanceProcAddr(instance_, "vkDestroyDebugUtilsMessengerEXT"));
    if (destroy) destroy(instance_, messenger_, nullptr);
    messenger_ = VK_NULL_HANDLE;
  }
  if (instance_) vkDestroyInstance(instance_, nullptr);
  instance_ = VK_NULL_HANDLE;
}

void VulkanContext::create_instance(const DeviceOptions& options, const Window* window) {
  const std::vector<std::string> window_extensions = window ? window_instance_extensions() : std::vector<std::string>{};
  std::vector<const char*> extensions;
  for (const auto& e : window_extensions) extensions.push_back(e.c_str());
  std::vector<const char*> layers;
  if (options.validation) {
    if (!has_layer(kValidationLayer)) {
      throw VulkanError(
          "validation was requested but VK_LAYER_KHRONOS_validation is not installed "
          "(Debian package vulkan-validationlayers)");
    }
    layers.push_back(kValidationLayer);
    extensions.push_back(VK_EXT_DEBUG_UTILS_EXTENSION_NAME);
  }

  VkApplicationInfo app{VK_STRUCTURE_TYPE_APPLICATION_INFO};
  app.pApplicationName = "needle-sim";
  app.pEngineName = "needle-sim";
  app.apiVersion = VK_API_VERSION_1_1;

  VkDebugUtilsMessengerCreateInfoEXT messenger_info{VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT};
  messenger_info.messageSeverity =
      VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
  messenger_info.messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT |
                               VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT |
                               VK_DEBUG_UTILS_MESSAGE_TYPE_PERFORMANCE_BIT_EXT;
  messenger_info.pfnUserCallback = &VulkanContext::on_debug_message;
  messenger_info.pUserData = this;

  // Synchronization validation catches missing barriers (compute -> vertex hand-offs among them).
  VkValidationFeatureEnableEXT sync_validation = VK_VALIDATION_FEATURE_ENABLE_SYNCHRONIZATION_VALIDATION_EXT;
  VkValidationFeaturesEXT features{VK_STRUCTURE_TYPE_VALIDATION_FEATURES_EXT};
  features.enabledValidationFeatureCount = 1;
  features.pEnabledValidationFeatures = &sync_validation;
  features.pNext = &messenger_info;  // messages during vkCreateInstance too

  VkInstanceCreateInfo info{VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO};
  info.pApplicationInfo = &app;
  info.enabledExtensionCount = static_cast<uint32_t>(extensions.size());
  info.ppEnabledExtensionNames = extensions.data();
  info.enabledLayerCount = static_cast<uint32_t>(layers.size());
  info.ppEnabledLayerNames = layers.data();
  if (options.validation) info.pNext = &features;
  VK_CHECK(vkCreateInstance(&info, nullptr, &instance_));

  if (options.validation) {
    auto create = reinterpret_cast<PFN_vkCreateDebugUtilsMessengerEXT>(
        vkGetInstanceProcAddr(instance_, "vkCreateDebugUtilsMessengerEXT"));
    if (!create) throw VulkanError("vkCreateDebugUtilsMessengerEXT is not available");
    VK_CHECK(create(instance_, &messenger_info, nullptr, &messenger_));
  }
}

VKAPI_ATTR VkBool32 VKAPI_CALL VulkanContext::on_debug_message(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                                               VkDebugUtilsMessageTypeFlagsEXT,
                                                               const VkDebugUtilsMessengerCallbackDataEXT* data,
                                                               void* self) {
  auto* context = static_cast<VulkanContext*>(self);
  std::string text = std::string(severity >= VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT ? "error: " : "warning: ") +
                     (data && data->pMessage ? data->pMessage : "(no text)");
  std::fprintf(stderr, "Vulkan validation %s\n", text.c_str());
  std::lock_guard lock(context->messages_mutex_);
  context->messages_.push_back(std::move(text));
  return VK_FALSE;
}

std::vector<std::string> VulkanContext::validation_messages() const {
  std::lock_guard lock(messages_mutex_);
  return messages_;
}

void VulkanContext::pick_physical_device() {
  uint32_t count = 0;
  VK_CHECK(vkEnumeratePhysicalDevices(instance_, &count, nullptr));
  std::vector<VkPhysicalDevice> devices(count);
  VK_CHECK(vkEnumeratePhysicalDevices(instance_, &count, devices.data()));

  int best_rank = 0;
  std::string rejected;
  for (VkPhysicalDevice candidate : devices) {
    VkPhysicalDeviceProperties props;
    vkGetPhysicalDeviceProperties(candidate, &props);
    uint32_t family_count = 0;
    vkGetPhysicalDeviceQueueFamilyProperties(candidate, &family_count, nullptr);
    std::vector<VkQueueFamilyProperties> families(family_count);
    vkGetPhysicalDeviceQueueFamilyProperties(candidate, &family_count, families.data());
    // One queue family for graphics, compute, transfer and (when windowed) present keeps the
    // hand-offs simple; every device we target has one.
    std::optional<uint32_t> family;
    for (uint32_t i = 0; i < family_count; ++i) {
      bool graphics =
          (families[i].queueFlags & VK_QUEUE_GRAPHICS_BIT) && (families[i].queueFlags & VK_QUEUE_COMPUTE_BIT);
      VkBool32 present = VK_TRUE;
      if (surface_) vkGetPhysicalDeviceSurfaceSupportKHR(candidate, i, surface_, &present);
      if (graphics && present) {
        family = i;
        break;
      }
    }
    int rank = type_rank(props.deviceType);
    if (!family) {
      rejected +=
          std::string(" ") + props.deviceName + " (no graphics+compute" + (surface_ ? "+present" : "") + " queue);";
      continue;
    }
    if (props.apiVersion < VK_API_VERSION_1_1) {
      rejected += std::string(" ") + props.deviceName + " (Vulkan < 1.1);";
      continue;
    }
    if (rank > best_rank) {
      best_rank = rank;
      physical_device_ = candidate;
      properties_ = props;
      queue_family_ = *family;
      timestamp_valid_bits_ = families[*family].timestampValidBits;
    }
  }
  if (!physical_device_) {
    throw VulkanError("no usable Vulkan device" + (rejected.empty()
                                                       ? std::string(" (none found: is mesa-vulkan-drivers installed?)")
                                                       : ":" + rejected));
  }
  vkGetPhysicalDeviceMemoryProperties(physical_device_, &memory_properties_);
}

void VulkanContext::create_device() {
  float priority = 1.0f;
  VkDeviceQueueCreateInfo queue_info{VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO};
  queue_info.queueFamilyIndex = queue_family_;
  queue_info.queueCount = 1;
  queue_info.pQueuePriorities = &priority;

  std::vector<const char*> extensions;
  if (surface_) extensions.push_back(VK_KHR_SWAPCHAIN_EXTENSION_NAME);
  // A CPU device's window takes frames written into memory shared with the X server
  // (engine/vulkan/shared_memory_images.hpp): that memory is imported as the image's.
  if (surface_ && properties_.deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU) {
    uint32_t count = 0;
    VK_CHECK(vkEnumerateDeviceExtensionProperties(physical_device_, nullptr, &count, nullptr));
    std::vector<VkExtensionProperties> offered(count);
    VK_CHECK(vkEnumerateDeviceExtensionProperties(physical_device_, nullptr, &count, offered.data()));
    for (const VkExtensionProperties& e : offered)
      if (std::string_view(e.extensionName) == VK_EXT_EXTERNAL_MEMORY_HOST_EXTENSION_NAME) imports_host_memory_ = true;
    if (imports_host_memory_) extensions.push_back(VK_EXT_EXTERNAL_MEMORY_HOST_EXTENSION_NAME);
  }

  // Two-channel float storage images: the ultrasound's echoes (engine/ultrasound/ultrasound_pass.cpp).
  VkPhysicalDeviceFeatures offered_features{}, features{};
  vkGetPhysicalDeviceFeatures(physical_device_, &offered_features);
  features.shaderStorageImageExtendedFormats = offered_features.shaderStorageImageExtendedFormats;
  storage_image_extended_formats_ = features.shaderStorageImageExtendedFormats == VK_TRUE;
  VkDeviceCreateInfo info{VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO};
  info.pEnabledFeatures = &features;
  info.queueCreateInfoCount = 1;
  info.pQueueCreateInfos = &queue_info;
  info.enabledExtensionCount = static_cast<uint32_t>(extensions.size());
  info.ppEnabledExtensionNames = extensions.data();
  VK_CHECK(vkCreateDevice(physical_device_, &info, nullptr, &device_));
  vkGetDeviceQueue(device_, queue_family_, 0, &queue_);

  VkCommandPoolCreateInfo pool_info{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
  pool_info.flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT;
  pool_info.queueFamilyIndex = queue_family_;
  VK_CHECK(vkCreateCommandPool(device_, &pool_info, nullptr, &command_pool_));
}

std::string VulkanContext::device_description() const {
  return std::string(properties_.deviceName) + " [" + type_name(properties_.deviceType) + ", Vulkan " +
         std::to_string(VK_API_VERSION_MAJOR(properties_.apiVersion)) + "." +
         std::to_string(VK_API_VERSION_MINOR(properties_.apiVersion)) + "]";
}

uint32_t VulkanContext::memory_type(uint32_t allowed_types, VkMemoryPropertyFlags flags) const {
  for (uint32_t i = 0; i < memory_properties_.memoryTypeCount; ++i) {
    if ((allowed_types & (1u << i)) && (memory_properties_.memoryTypes[i].propertyFlags & flags) == flags) return i;
  }
  throw VulkanError("no Vulkan memory type with the required properties");
}

double VulkanContext::timestamp_period_ns() const {
  if (timestamp_valid_bits_ == 0 || !properties_.limits.timestampComputeAndGraphics) return 0.0;
  return properties_.limits.timestampPeriod;
}

VkSampleCountFlagBits VulkanContext::max_msaa(int wanted) const {
  VkSampleCountFlags supported = properties_.limits.framebufferColorSampleCounts &
                                 properties_.limits.framebufferDepthSampleCounts &
                                 properties_.limits.framebufferStencilSampleCounts;
  for (int s = wanted; s > 1; s >>= 1) {
    if (supported & s) return static_cast<VkSampleCountFlagBits>(s);
  }
  return VK_SAMPLE_COUNT_1_BIT;
}

void VulkanContext::submit_and_wait(const std::function<void(VkCommandBuffer)>& record) const {
  VkCommandBufferAllocateInfo alloc{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
  alloc.commandPool = command_pool_;
  alloc.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
  alloc.commandBufferCount = 1;
  VkCommandBuffer cmd;
  VK_CHECK(vkAllocateCommandBuffers(device_, &alloc, &cmd));
  VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
  begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
  VK_CHECK(vkBeginCommandBuffer(cmd, &begin));
  record(cmd);
  VK_CHECK(vkEndCommandBuffer(cmd));
  VkSubmitInfo submit{VK_STRUCTURE_TYPE_SUBMIT_INFO};
  submit.commandBufferCount = 1;
  submit.pCommandBuffers = &cmd;
  VK_CHECK(vkQueueSubmit(queue_, 1, &submit, VK_NULL_HANDLE));
  VK_CHECK(vkQueueWaitIdle(queue_));
  vkFreeCommandBuffers(device_, command_pool_, 1, &cmd);
}

}  // namespace needle::engine
