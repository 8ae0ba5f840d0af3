// Every Vulkan test runs under the Khronos validation layer; any message it sends fails the test.
#pragma once

#include <gtest/gtest.h>

#include <memory>

#include "engine/vulkan_context.hpp"

namespace needle::test {

class VulkanTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    engine::ContextOptions options;
    options.validation = true;
    options.announce_device = false;
    context_ = std::make_unique<engine::VulkanContext>(options);
  }
  static void TearDownTestSuite() { context_.reset(); }
  void TearDown() override {
    auto messages = context_->validation_messages();
    for (size_t i = seen_messages_; i < messages.size(); ++i) ADD_FAILURE() << "Vulkan validation " << messages[i];
    seen_messages_ = messages.size();
  }
  const engine::VulkanContext& context() const { return *context_; }

  static inline std::unique_ptr<engine::VulkanContext> context_;
  static inline size_t seen_messages_ = 0;
};

}  // namespace needle::test
