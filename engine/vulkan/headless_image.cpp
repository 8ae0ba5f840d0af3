#include "engine/vulkan/headless_image.hpp"

namespace needle::engine {

HeadlessImage::HeadlessImage(const VulkanContext& context, VkExtent2D extent)
    : image_(context, {extent, kHeadlessFormat, VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT}),
      views_{image_.view()} {}

}  // namespace needle::engine
