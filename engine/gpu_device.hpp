// The GPU the engine draws with, chosen and opened once: the first object an application makes,
// handed to every target, renderer and pass after it. Its Vulkan objects stay inside the engine.
#pragma once

#include <memory>
#include <string>
#include <vector>

namespace needle::engine {

class VulkanContext;
class Window;

struct DeviceOptions {
  // The Khronos validation layer and its messages (validation_messages()). Default: on in debug
  // builds or when the environment has NEEDLE_VALIDATION=1. Tests turn it on.
  bool validation = validation_by_default();
  // Print the chosen device on stdout.
  bool announce_device = true;

  static bool validation_by_default();
};

class GpuDevice {
 public:
  // A device for offscreen targets only.
  explicit GpuDevice(const DeviceOptions& options = {});
  // A device that can also present to this window (a WindowTarget on it).
  explicit GpuDevice(const Window& window, const DeviceOptions& options = {});
  ~GpuDevice();
  GpuDevice(const GpuDevice&) = delete;
  GpuDevice& operator=(const GpuDevice&) = delete;

  // "NAME [TYPE, Vulkan X.Y]", e.g. "llvmpipe (...) [CPU, Vulkan 1.3]".
  std::string device_description() const;
  // A CPU device (Mesa's lavapipe) pays for every MSAA sample in frame time, so the interactive
  // window asks for fewer there (docs/RENDERING.md, MSAA).
  bool is_cpu_device() const;
  // Whether the device writes timestamps in graphics and compute work (FrameCost's device times),
  // and the nanoseconds a timestamp tick lasts; 0 when it has none.
  double timestamp_period_ns() const;
  // Every message the validation layer sent (warnings and errors), in order.
  std::vector<std::string> validation_messages() const;

  // The engine's own access (engine/vulkan/vulkan_context.hpp); an incomplete type outside it.
  const VulkanContext& context() const { return *context_; }

 private:
  std::unique_ptr<VulkanContext> context_;
};

}  // namespace needle::engine
