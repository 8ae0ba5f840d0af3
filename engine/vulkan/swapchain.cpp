#include "engine/vulkan/swapchain.hpp"

#include <algorithm>

#include "engine/vulkan/vk_check.hpp"
#include "engine/vulkan/vulkan_context.hpp"
#include "engine/window.hpp"

namespace needle::engine {
namespace {

VkSurfaceFormatKHR choose_format(VkPhysicalDevice device, VkSurfaceKHR surface) {
  uint32_t count = 0;
  VK_CHECK(vkGetPhysicalDeviceSurfaceFormatsKHR(device, surface, &count, nullptr));
  std::vector<VkSurfaceFormatKHR> formats(count);
  VK_CHECK(vkGetPhysicalDeviceSurfaceFormatsKHR(device, surface, &count, formats.data()));
  if (formats.empty()) throw VulkanError("the window surface offers no formats");
  // UNORM, holding sRGB-encoded values written by the shaders (docs/RENDERING.md, "Colour"): a
  // CPU device encodes an sRGB format's every write, blend and blit texel in software.
  for (VkFormat wanted : {VK_FORMAT_B8G8R8A8_UNORM, VK_FORMAT_R8G8B8A8_UNORM}) {
    for (const auto& f : formats) {
      if (f.format == wanted && f.colorSpace == VK_COLOR_SPACE_SRGB_NONLINEAR_KHR) return f;
    }
  }
  throw VulkanError("the window surface offers no 8-bit UNORM format in the sRGB colour space");
}

}  // namespace

Swapchain::Swapchain(const VulkanContext& context, Window& window) : context_(context), window_(window) {
  format_ = choose_format(context.physical_device(), context.surface()).format;
  recreate();
}

Swapchain::~Swapchain() {
  vkDeviceWaitIdle(context_.device());
  destroy_views();
  if (swapchain_) vkDestroySwapchainKHR(context_.device(), swapchain_, nullptr);
}

void Swapchain::destroy_views() {
  for (VkImageView v : views_) vkDestroyImageView(context_.device(), v, nullptr);
  views_.clear();
}

bool Swapchain::recreate() {
  const Extent wanted = window_.framebuffer_extent();
  if (wanted.width == 0 || wanted.height == 0) return false;  // minimised
  vkDeviceWaitIdle(context_.device());

  VkSurfaceCapabilitiesKHR caps;
  VK_CHECK(vkGetPhysicalDeviceSurfaceCapabilitiesKHR(context_.physical_device(), context_.surface(), &caps));
  if (caps.currentExtent.width != UINT32_MAX) {
    extent_ = caps.currentExtent;
  } else {
    extent_.width = std::clamp(wanted.width, caps.minImageExtent.width, caps.maxImageExtent.width);
    extent_.height = std::clamp(wanted.height, caps.minImageExtent.height, caps.maxImageExtent.height);
  }
  if (extent_.width == 0 || extent_.height == 0) return false;
  uint32_t image_count = caps.minImageCount + 1;
  if (caps.maxImageCount) image_count = std::min(image_count, caps.maxImageCount);

  VkSwapchainCreateInfoKHR info{VK_STRUCTURE_TYPE_SWAPCHAIN_CREATE_INFO_KHR};
  info.surface = context_.surface();
  info.minImageCount = image_count;
  info.imageFormat = format_;
  info.imageColorSpace = VK_COLOR_SPACE_SRGB_NONLINEAR_KHR;
  info.imageExtent = extent_;
  info.imageArrayLayers = 1;
  // TRANSFER_SRC lets tests screenshot the presented image.
  info.imageUsage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | (caps.supportedUsageFlags & VK_IMAGE_USAGE_TRANSFER_SRC_BIT);
  info.imageSharingMode = VK_SHARING_MODE_EXCLUSIVE;
  info.preTransform = caps.currentTransform;
  info.compositeAlpha = VK_COMPOSITE_ALPHA_OPAQUE_BIT_KHR;
  info.presentMode =
      present_mode_;  // FIFO unless set_present_mode: always available; paces the frame loop to the display
  info.clipped = VK_TRUE;
  info.oldSwapchain = swapchain_;
  VkSwapchainKHR fresh;
  VK_CHECK(vkCreateSwapchainKHR(context_.device(), &info, nullptr, &fresh));
  destroy_views();
  if (swapchain_) vkDestroySwapchainKHR(context_.device(), swapchain_, nullptr);
  swapchain_ = fresh;

  uint32_t count = 0;
  VK_CHECK(vkGetSwapchainImagesKHR(context_.device(), swapchain_, &count, nullptr));
  images_.resize(count);
  VK_CHECK(vkGetSwapchainImagesKHR(context_.device(), swapchain_, &count, images_.data()));
  for (VkImage image : images_) {
    VkImageViewCreateInfo view{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
    view.image = image;
    view.viewType = VK_IMAGE_VIEW_TYPE_2D;
    view.format = format_;
    view.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
    VkImageView v;
    VK_CHECK(vkCreateImageView(context_.device(), &view, nullptr, &v));
    views_.push_back(v);
  }
  generation_ = next_target_generation();
  stale_ = false;
  return true;
}

std::optional<uint32_t> Swapchain::acquire(VkSemaphore image_ready) {
  if (window_.take_resized()) stale_ = true;
  if ((stale_ || !swapchain_) && !recreate()) return std::nullopt;
  uint32_t index = 0;
  VkResult r = vkAcquireNextImageKHR(context_.device(), swapchain_, UINT64_MAX, image_ready, VK_NULL_HANDLE, &index);
  if (r == VK_ERROR_OUT_OF_DATE_KHR) {
    stale_ = true;  // nothing was signalled; try again next frame
    return std::nullopt;
  }
  if (r == VK_SUBOPTIMAL_KHR) {
    stale_ = true;  // the semaphore is signalled: draw this frame, recreate for the next
  } else {
    vk_check(r, "vkAcquireNextImageKHR");
  }
  return index;
}

bool Swapchain::set_present_mode(VkPresentModeKHR mode) {
  uint32_t count = 0;
  VK_CHECK(vkGetPhysicalDeviceSurfacePresentModesKHR(context_.physical_device(), context_.surface(), &count, nullptr));
  std::vector<VkPresentModeKHR> modes(count);
  VK_CHECK(
      vkGetPhysicalDeviceSurfacePresentModesKHR(context_.physical_device(), context_.surface(), &count, modes.data()));
  if (std::find(modes.begin(), modes.end(), mode) == modes.end()) return false;
  if (mode != present_mode_) stale_ = true;
  present_mode_ = mode;
  return true;
}

void Swapchain::present(uint32_t index, VkSemaphore render_done) {
  VkPresentInfoKHR info{VK_STRUCTURE_TYPE_PRESENT_INFO_KHR};
  info.waitSemaphoreCount = 1;
  info.pWaitSemaphores = &render_done;
  info.swapchainCount = 1;
  info.pSwapchains = &swapchain_;
  info.pImageIndices = &index;
  VkResult r = vkQueuePresentKHR(context_.queue(), &info);
  if (r == VK_ERROR_OUT_OF_DATE_KHR || r == VK_SUBOPTIMAL_KHR) {
    stale_ = true;
  } else {
    vk_check(r, "vkQueuePresentKHR");
  }
}

}  // namespace needle::engine
