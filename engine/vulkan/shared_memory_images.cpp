#include "engine/vulkan/shared_memory_images.hpp"

#include <sys/ipc.h>
#include <sys/shm.h>

#include <algorithm>
#include <string>

#include "engine/vulkan/vk_check.hpp"
#include "engine/vulkan/vulkan_context.hpp"
#include "engine/window.hpp"

// Last: Xlib's macros (None, Status, Bool, Success) would otherwise reach the headers above.
#define GLFW_EXPOSE_NATIVE_X11
#include <GLFW/glfw3.h>
#include <GLFW/glfw3native.h>
#include <X11/Xutil.h>
#include <X11/extensions/XShm.h>

namespace needle::engine {
namespace {

constexpr VkExternalMemoryHandleTypeFlagBits kHostMemory = VK_EXTERNAL_MEMORY_HANDLE_TYPE_HOST_ALLOCATION_BIT_EXT;
constexpr VkImageUsageFlags kUsage =
    VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT;  // drawn, captured

// Xlib reports a request's failure to one process-wide handler (by default: print and exit), so
// attaching a segment, which fails on a server on another machine, is tried with this one in place.
bool g_x_error = false;
int note_x_error(Display*, XErrorEvent*) {
  g_x_error = true;
  return 0;
}

// (display, segment with shmid and shmaddr set) => the server attached it (true) or refused (false).
bool attach(Display* display, XShmSegmentInfo& segment) {
  XSync(display, False);
  g_x_error = false;
  XErrorHandler previous = XSetErrorHandler(note_x_error);
  const bool sent = XShmAttach(display, &segment);
  XSync(display, False);
  XSetErrorHandler(previous);
  return sent && !g_x_error;
}

// A 32-bit pixel with blue in the lowest byte is VK_FORMAT_B8G8R8A8_UNORM's memory order.
bool is_bgrx(Display* display, const XWindowAttributes& attributes) {
  const Visual* v = attributes.visual;
  return ImageByteOrder(display) == LSBFirst && (attributes.depth == 24 || attributes.depth == 32) &&
         v->red_mask == 0xff0000 && v->green_mask == 0x00ff00 && v->blue_mask == 0x0000ff;
}

// A private System V segment of `bytes` attached here (segment.shmid and shmaddr set, read-only to
// the server), removed once both sides detach; false, nothing attached, where the system refuses.
bool make_segment(XShmSegmentInfo& segment, size_t bytes) {
  segment.shmid = shmget(IPC_PRIVATE, bytes, IPC_CREAT | 0600);
  if (segment.shmid < 0) return false;
  void* at = shmat(segment.shmid, nullptr, 0);
  shmctl(segment.shmid, IPC_RMID, nullptr);
  if (at == reinterpret_cast<void*>(-1)) return false;
  segment.shmaddr = static_cast<char*>(at);
  segment.readOnly = True;
  return true;
}

VkDeviceSize host_pointer_alignment(const VulkanContext& context) {
  VkPhysicalDeviceExternalMemoryHostPropertiesEXT host{
      VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_EXTERNAL_MEMORY_HOST_PROPERTIES_EXT};
  VkPhysicalDeviceProperties2 properties{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2, &host};
  vkGetPhysicalDeviceProperties2(context.physical_device(), &properties);
  return host.minImportedHostPointerAlignment;
}

bool imports_linear_images(const VulkanContext& context) {
  VkPhysicalDeviceExternalImageFormatInfo external{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_EXTERNAL_IMAGE_FORMAT_INFO};
  external.handleType = kHostMemory;
  VkPhysicalDeviceImageFormatInfo2 info{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_IMAGE_FORMAT_INFO_2, &external};
  info.format = VK_FORMAT_B8G8R8A8_UNORM;
  info.type = VK_IMAGE_TYPE_2D;
  info.tiling = VK_IMAGE_TILING_LINEAR;
  info.usage = kUsage;
  VkExternalImageFormatProperties external_properties{VK_STRUCTURE_TYPE_EXTERNAL_IMAGE_FORMAT_PROPERTIES};
  VkImageFormatProperties2 properties{VK_STRUCTURE_TYPE_IMAGE_FORMAT_PROPERTIES_2, &external_properties};
  if (vkGetPhysicalDeviceImageFormatProperties2(context.physical_device(), &info, &properties) != VK_SUCCESS)
    return false;
  return external_properties.externalMemoryProperties.externalMemoryFeatures &
         VK_EXTERNAL_MEMORY_FEATURE_IMPORTABLE_BIT;
}

}  // namespace

struct SharedMemoryImages::X11 {
  Display* display = nullptr;
  ::Window window = 0;
  XWindowAttributes attributes{};
  GC gc = nullptr;
  XShmSegmentInfo segment{};
  XImage* image = nullptr;  // over the segment, rowPitch / 4 pixels wide
  bool attached = false;    // the server holds the segment

  // The XImage alone (its pixels are the segment's, not Xlib's to free).
  void drop_image() {
    if (!image) return;
    image->data = nullptr;
    XDestroyImage(image);
    image = nullptr;
  }
  void release() {
    if (attached) {
      XShmDetach(display, &segment);
      XSync(display, False);
      attached = false;
    }
    drop_image();
    if (segment.shmaddr) shmdt(segment.shmaddr);
    segment = {};
  }
};

std::string SharedMemoryImages::unavailable(const VulkanContext& context, const Window& window) {
  if (!context.imports_host_memory())
    return "the Vulkan device cannot draw into host memory (no VK_EXT_external_memory_host)";
  if (!imports_linear_images(context))
    return "the Vulkan device cannot draw a linear BGRA8 image in imported host memory";
  Display* display = glfwGetX11Display();
  const ::Window x_window = display ? glfwGetX11Window(window.handle()) : 0;
  if (!display || !x_window) return "not an X11 window";
  if (!XShmQueryExtension(display)) return "the X server has no MIT-SHM";
  XWindowAttributes attributes;
  if (!XGetWindowAttributes(display, x_window, &attributes) || !is_bgrx(display, attributes))
    return "the window's visual is not 32-bit BGRX";
  XShmSegmentInfo probe{};
  if (!make_segment(probe, 4096)) return "no shared memory segment could be made here (shmget, shmat)";
  const bool attached = attach(display, probe);
  if (attached) {
    XShmDetach(display, &probe);
    XSync(display, False);
  }
  shmdt(probe.shmaddr);
  return attached ? "" : "the X server cannot attach this process's shared memory (a server on another machine?)";
}

SharedMemoryImages::SharedMemoryImages(const VulkanContext& context, Window& window)
    : context_(context), window_(window), x11_(std::make_unique<X11>()) {
  if (const std::string why = unavailable(context, window); !why.empty())
    throw VulkanError("X11 shared memory presentation: " + why);
  x11_->display = glfwGetX11Display();
  x11_->window = glfwGetX11Window(window.handle());
  XGetWindowAttributes(x11_->display, x11_->window, &x11_->attributes);
  x11_->gc = XCreateGC(x11_->display, x11_->window, 0, nullptr);
  try {
    recreate();
  } catch (...) {
    release();  // no destructor runs for an object not made
    XFreeGC(x11_->display, x11_->gc);
    throw;
  }
}

SharedMemoryImages::~SharedMemoryImages() {
  release();
  XFreeGC(x11_->display, x11_->gc);
}

void SharedMemoryImages::release() {
  vkDeviceWaitIdle(context_.device());
  pending_ = false;  // a frame of the old size: the next one replaces it
  for (VkImageView v : views_) vkDestroyImageView(context_.device(), v, nullptr);
  views_.clear();
  if (image_) vkDestroyImage(context_.device(), image_, nullptr);
  if (memory_) vkFreeMemory(context_.device(), memory_, nullptr);
  image_ = VK_NULL_HANDLE;
  memory_ = VK_NULL_HANDLE;
  x11_->release();
}

bool SharedMemoryImages::recreate() {
  const Extent wanted = window_.framebuffer_extent();
  if (wanted.width == 0 || wanted.height == 0) return false;  // minimised
  release();
  const VkDevice device = context_.device();
  extent_ = {wanted.width, wanted.height};

  VkExternalMemoryImageCreateInfo external{VK_STRUCTURE_TYPE_EXTERNAL_MEMORY_IMAGE_CREATE_INFO};
  external.handleTypes = kHostMemory;
  VkImageCreateInfo info{VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO, &external};
  info.imageType = VK_IMAGE_TYPE_2D;
  info.format = format();
  info.extent = {extent_.width, extent_.height, 1};
  info.mipLevels = 1;
  info.arrayLayers = 1;
  info.samples = VK_SAMPLE_COUNT_1_BIT;
  info.tiling = VK_IMAGE_TILING_LINEAR;  // rows as the XImage has them
  info.usage = kUsage;
  info.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
  VK_CHECK(vkCreateImage(device, &info, nullptr, &image_));
  VkMemoryRequirements needs;
  vkGetImageMemoryRequirements(device, image_, &needs);
  const VkImageSubresource colour{VK_IMAGE_ASPECT_COLOR_BIT, 0, 0};
  VkSubresourceLayout layout;
  vkGetImageSubresourceLayout(device, image_, &colour, &layout);
  if (layout.offset != 0 || layout.rowPitch % 4 != 0)
    throw VulkanError("X11 shared memory presentation: the device lays the image's rows out at offset " +
                      std::to_string(layout.offset) + ", pitch " + std::to_string(layout.rowPitch) + " bytes");

  // The segment: whole pages of the import's alignment, holding the image as the device lays it out.
  const VkDeviceSize alignment = std::max<VkDeviceSize>(host_pointer_alignment(context_), 1);
  const VkDeviceSize bytes =
      (std::max(needs.size, layout.rowPitch * extent_.height) + alignment - 1) / alignment * alignment;
  X11& x = *x11_;
  if (!make_segment(x.segment, bytes))
    throw VulkanError("X11 shared memory presentation: no segment of " + std::to_string(bytes) +
                      " bytes (shmget, shmat)");
  x.image = XShmCreateImage(x.display, x.attributes.visual, unsigned(x.attributes.depth), ZPixmap, x.segment.shmaddr,
                            &x.segment, unsigned(layout.rowPitch / 4), extent_.height);
  if (!x.image || x.image->bits_per_pixel != 32 || size_t(x.image->bytes_per_line) != layout.rowPitch)
    throw VulkanError(
        "X11 shared memory presentation: the server's image of this window is not 32 bits a pixel, rows of " +
        std::to_string(layout.rowPitch) + " bytes");
  if (!attach(x.display, x.segment))
    throw VulkanError("X11 shared memory presentation: the X server refused the segment");
  x.attached = true;

  auto host_pointer_properties = reinterpret_cast<PFN_vkGetMemoryHostPointerPropertiesEXT>(
      vkGetDeviceProcAddr(device, "vkGetMemoryHostPointerPropertiesEXT"));
  VkMemoryHostPointerPropertiesEXT pointer{VK_STRUCTURE_TYPE_MEMORY_HOST_POINTER_PROPERTIES_EXT};
  VK_CHECK(host_pointer_properties(device, kHostMemory, x.segment.shmaddr, &pointer));
  VkImportMemoryHostPointerInfoEXT import{VK_STRUCTURE_TYPE_IMPORT_MEMORY_HOST_POINTER_INFO_EXT};
  import.handleType = kHostMemory;
  import.pHostPointer = x.segment.shmaddr;
  VkMemoryAllocateInfo allocate{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO, &import};
  allocate.allocationSize = bytes;
  allocate.memoryTypeIndex = context_.memory_type(needs.memoryTypeBits & pointer.memoryTypeBits, 0);
  VK_CHECK(vkAllocateMemory(device, &allocate, nullptr, &memory_));
  VK_CHECK(vkBindImageMemory(device, image_, memory_, 0));

  VkImageViewCreateInfo view{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
  view.image = image_;
  view.viewType = VK_IMAGE_VIEW_TYPE_2D;
  view.format = format();
  view.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
  VkImageView v;
  VK_CHECK(vkCreateImageView(device, &view, nullptr, &v));
  views_.push_back(v);
  generation_ = next_target_generation();
  stale_ = false;
  return true;
}

std::optional<uint32_t> SharedMemoryImages::acquire(VkSemaphore) {
  show_pending();
  if (window_.take_resized()) stale_ = true;
  if ((stale_ || !image_) && !recreate()) return std::nullopt;
  return 0;
}

void SharedMemoryImages::present(uint32_t, VkSemaphore) { pending_ = true; }

void SharedMemoryImages::show_pending() {
  if (!pending_) return;
  pending_ = false;
  VK_CHECK(vkQueueWaitIdle(context_.queue()));
  X11& x = *x11_;
  XShmPutImage(x.display, x.window, x.gc, x.image, 0, 0, 0, 0, extent_.width, extent_.height, False);
  XSync(x.display, False);  // the server has copied the segment: the next frame may draw into it
}

}  // namespace needle::engine
