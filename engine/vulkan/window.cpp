// The public Window and, in the same place as GLFW's set-up, the Vulkan side of it
// (window_surface.hpp).
#include "engine/window.hpp"

#define GLFW_INCLUDE_VULKAN
#include <GLFW/glfw3.h>

#include <cstdlib>
#include <stdexcept>

#include "engine/vulkan/vk_check.hpp"
#include "engine/vulkan/window_surface.hpp"

namespace needle::engine {
namespace {

// GLFW is initialised once per process and torn down at exit.
bool glfw_ready() {
  static const bool ready = [] {
    glfwSetErrorCallback([](int, const char*) {});  // failures surface through return values
    if (!glfwInit()) return false;
    std::atexit(glfwTerminate);
    return true;
  }();
  return ready;
}

}  // namespace

bool Window::display_available() {
  const char* x = std::getenv("DISPLAY");
  const char* wayland = std::getenv("WAYLAND_DISPLAY");
  if ((!x || !*x) && (!wayland || !*wayland)) return false;
  return glfw_ready() && glfwVulkanSupported();
}

std::vector<std::string> window_instance_extensions() {
  if (!glfw_ready()) throw std::runtime_error("no display: GLFW could not initialise");
  uint32_t count = 0;
  const char** names = glfwGetRequiredInstanceExtensions(&count);
  if (!names) throw std::runtime_error("GLFW reports that Vulkan cannot present to its windows here");
  return std::vector<std::string>(names, names + count);
}

Window::Window(const std::string& title, int width, int height) {
  if (!glfw_ready()) throw std::runtime_error("no display: GLFW could not initialise");
  glfwWindowHint(GLFW_CLIENT_API, GLFW_NO_API);
  glfwWindowHint(GLFW_RESIZABLE, GLFW_TRUE);
  window_ = glfwCreateWindow(width, height, title.c_str(), nullptr, nullptr);
  if (!window_) throw std::runtime_error("GLFW could not create a window");
  glfwSetWindowUserPointer(window_, this);
  glfwSetFramebufferSizeCallback(window_, [](GLFWwindow* w, int, int) {
    static_cast<Window*>(glfwGetWindowUserPointer(w))->resized_ = true;
  });
  // Installed before the UI pass's ImGui backend, which chains to them.
  glfwSetScrollCallback(window_, [](GLFWwindow* w, double, double dy) {
    static_cast<Window*>(glfwGetWindowUserPointer(w))->scroll_ += dy;
  });
  glfwSetKeyCallback(window_, [](GLFWwindow* w, int key, int, int action, int mods) {
    if (action == GLFW_RELEASE) return;
    auto* self = static_cast<Window*>(glfwGetWindowUserPointer(w));
    if (key == GLFW_KEY_UP || key == GLFW_KEY_DOWN) self->scroll_ += key == GLFW_KEY_UP ? 1.0 : -1.0;
    if (self->key_presses_.size() < kMaxKeyPresses) self->key_presses_.push_back({key, (mods & GLFW_MOD_SHIFT) != 0});
  });
}

Window::~Window() {
  if (window_) glfwDestroyWindow(window_);
}

VkSurfaceKHR create_window_surface(const Window& window, VkInstance instance) {
  VkSurfaceKHR surface;
  VK_CHECK(glfwCreateWindowSurface(instance, window.handle(), nullptr, &surface));
  return surface;
}

bool Window::should_close() const { return glfwWindowShouldClose(window_); }
void Window::request_close() { glfwSetWindowShouldClose(window_, GLFW_TRUE); }
void Window::poll_events() const { glfwPollEvents(); }
void Window::wait_events() const { glfwWaitEventsTimeout(0.1); }

Extent Window::framebuffer_extent() const {
  int w = 0, h = 0;
  glfwGetFramebufferSize(window_, &w, &h);
  return {uint32_t(w), uint32_t(h)};
}

void Window::cursor_normalized(double& x, double& y) const {
  double px = 0.0, py = 0.0;
  int w = 1, h = 1;
  glfwGetCursorPos(window_, &px, &py);
  glfwGetWindowSize(window_, &w, &h);
  x = w > 0 ? 2.0 * px / w - 1.0 : 0.0;
  y = h > 0 ? 1.0 - 2.0 * py / h : 0.0;
}

double Window::take_scroll() {
  const double steps = scroll_;
  scroll_ = 0.0;
  return steps;
}

std::vector<Window::KeyPress> Window::take_key_presses() {
  std::vector<KeyPress> presses;
  presses.swap(key_presses_);
  return presses;
}

bool Window::take_resized() {
  bool r = resized_;
  resized_ = false;
  return r;
}

}  // namespace needle::engine
