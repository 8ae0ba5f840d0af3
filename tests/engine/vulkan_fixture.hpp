// Every Vulkan test runs under the Khronos validation layer; any message it sends fails the test.
#pragma once

#include <gtest/gtest.h>

#include <memory>

#include "engine/gpu_device.hpp"

namespace needle::test {

class VulkanTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    device_ = std::make_unique<engine::GpuDevice>(engine::DeviceOptions{.validation = true, .announce_device = false});
  }
  static void TearDownTestSuite() { device_.reset(); }
  void TearDown() override {
    auto messages = device_->validation_messages();
    for (size_t i = seen_messages_; i < messages.size(); ++i) ADD_FAILURE() << "Vulkan validation " << messages[i];
    seen_messages_ = messages.size();
  }
  const engine::GpuDevice& device() const { return *device_; }
  // For tests of the engine's internals (engine/vulkan/vulkan_context.hpp).
  const engine::VulkanContext& context() const { return device_->context(); }

  static inline std::unique_ptr<engine::GpuDevice> device_;
  static inline size_t seen_messages_ = 0;
};

}  // namespace needle::test
