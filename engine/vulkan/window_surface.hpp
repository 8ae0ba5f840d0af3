// Vulkan's side of a Window, for the context that presents to it: the instance extensions
// presenting needs, and the window's surface. Implemented beside GLFW's set-up (window.cpp).
#pragma once

#include <vulkan/vulkan.h>

#include <string>
#include <vector>

namespace needle::engine {

class Window;

// Throws std::runtime_error when there is no display or Vulkan cannot present to its windows.
std::vector<std::string> window_instance_extensions();
VkSurfaceKHR create_window_surface(const Window& window, VkInstance instance);

}  // namespace needle::engine
