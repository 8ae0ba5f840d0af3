#include "engine/passes/frame_capture.hpp"

#include <cstring>
#include <utility>
#include <vector>

#include "engine/vulkan/gpu_image.hpp"
#include "engine/vulkan/target_images.hpp"

namespace needle::engine {

void FrameCapture::record(VkCommandBuffer cmd, const TargetImages& target, uint32_t image) {
  VkExtent2D e = target.extent();
  VkDeviceSize bytes = VkDeviceSize(e.width) * e.height * 4;
  if (buffer_.size() != bytes) buffer_ = GpuBuffer::host_visible(context_, bytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT);
  transition_image(cmd, target.image(image), target.final_layout(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                   VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT, VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT,
                   VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_READ_BIT);
  VkBufferImageCopy region{};
  region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
  region.imageExtent = {e.width, e.height, 1};
  vkCmdCopyImageToBuffer(cmd, target.image(image), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, buffer_.handle(), 1, &region);
  // Back to the layout the target expects (present), after the copy has read it.
  transition_image(cmd, target.image(image), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, target.final_layout(),
                   VK_PIPELINE_STAGE_TRANSFER_BIT, 0, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, 0);
  VkMemoryBarrier to_host{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
  to_host.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
  to_host.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
  vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0, 1, &to_host, 0, nullptr, 0,
                       nullptr);
}

RgbaImage FrameCapture::read(const TargetImages& target) const {
  VkExtent2D e = target.extent();
  RgbaImage out{e.width, e.height, std::vector<uint8_t>(size_t(e.width) * e.height * 4)};
  std::memcpy(out.pixels.data(), buffer_.mapped(), out.pixels.size());
  if (target.format() == VK_FORMAT_B8G8R8A8_UNORM) {
    for (size_t i = 0; i < out.pixels.size(); i += 4) std::swap(out.pixels[i], out.pixels[i + 2]);
  }
  return out;
}

}  // namespace needle::engine
