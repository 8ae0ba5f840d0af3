#include "engine/headless_target.hpp"

namespace needle::engine {

HeadlessTarget::HeadlessTarget(const VulkanContext& context, VkExtent2D extent)
    : image_(context, {extent, VK_FORMAT_R8G8B8A8_SRGB,
                       VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT}),
      views_{image_.view()} {}

}  // namespace needle::engine
