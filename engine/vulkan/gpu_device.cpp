#include "engine/gpu_device.hpp"

#include <cstdlib>
#include <cstring>

#include "engine/vulkan/vulkan_context.hpp"

namespace needle::engine {

bool DeviceOptions::validation_by_default() {
  const char* env = std::getenv("NEEDLE_VALIDATION");
  if (env) return std::strcmp(env, "0") != 0;
#ifdef NEEDLE_VALIDATION_BY_DEFAULT
  return true;
#else
  return false;
#endif
}

GpuDevice::GpuDevice(const DeviceOptions& options) : context_(std::make_unique<VulkanContext>(options)) {}

GpuDevice::GpuDevice(const Window& window, const DeviceOptions& options)
    : context_(std::make_unique<VulkanContext>(options, &window)) {}

GpuDevice::~GpuDevice() = default;

std::string GpuDevice::device_description() const { return context_->device_description(); }

bool GpuDevice::is_cpu_device() const { return context_->properties().deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU; }

double GpuDevice::timestamp_period_ns() const { return context_->timestamp_period_ns(); }

std::vector<std::string> GpuDevice::validation_messages() const { return context_->validation_messages(); }

}  // namespace needle::engine
