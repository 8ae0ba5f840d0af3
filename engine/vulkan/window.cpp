// The public Window and, in the same place as GLFW's set-up, the Vulkan side of it
// (window_surface.hpp).
#include "engine/window.hpp"

#define GLFW_INCLUDE_VULKAN
#include <GLFW/glfw3.h>

#include <algorithm>
#include <cstdlib>
#include <iterator>
#include <stdexcept>

#include "engine/vulkan/vk_check.hpp"
#include "engine/vulkan/window_surface.hpp"

namespace needle::engine {
namespace {

// The application's name of a GLFW key code.
Key key_of(int key) {
  if (key >= GLFW_KEY_A && key <= GLFW_KEY_Z) return Key(int(Key::kA) + (key - GLFW_KEY_A));
  switch (key) {
    case GLFW_KEY_UP:
      return Key::kUp;
    case GLFW_KEY_DOWN:
      return Key::kDown;
    case GLFW_KEY_LEFT:
      return Key::kLeft;
    case GLFW_KEY_RIGHT:
      return Key::kRight;
    case GLFW_KEY_PAGE_UP:
      return Key::kPageUp;
    case GLFW_KEY_PAGE_DOWN:
      return Key::kPageDown;
    case GLFW_KEY_TAB:
      return Key::kTab;
    case GLFW_KEY_ENTER:
    case GLFW_KEY_KP_ENTER:
      return Key::kEnter;
    case GLFW_KEY_ESCAPE:
      return Key::kEscape;
    case GLFW_KEY_F3:
      return Key::kF3;
    default:
      return Key::kOther;
  }
}

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
  glfwSetFramebufferSizeCallback(
      window_, [](GLFWwindow* w, int, int) { static_cast<Window*>(glfwGetWindowUserPointer(w))->resized_ = true; });
  // Installed before the UI pass's ImGui backend, which chains to them.
  glfwSetScrollCallback(window_, [](GLFWwindow* w, double, double dy) {
    static_cast<Window*>(glfwGetWindowUserPointer(w))->scroll_ += dy;
  });
  glfwSetKeyCallback(window_, [](GLFWwindow* w, int key, int, int action, int mods) {
    if (action == GLFW_RELEASE) return;
    auto* self = static_cast<Window*>(glfwGetWindowUserPointer(w));
    if (key == GLFW_KEY_UP || key == GLFW_KEY_DOWN) self->scroll_ += key == GLFW_KEY_UP ? 1.0 : -1.0;
    if (self->key_presses_.size() < kMaxKeyPresses)
      self->key_presses_.push_back({key_of(key), (mods & GLFW_MOD_SHIFT) != 0});
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

Extent Window::size() const {
  int w = 0, h = 0;
  glfwGetWindowSize(window_, &w, &h);
  return {uint32_t(std::max(w, 0)), uint32_t(std::max(h, 0))};
}

Window::Cursor Window::cursor() const {
  Cursor at;
  glfwGetCursorPos(window_, &at.x, &at.y);
  return at;
}

void Window::set_cursor(const Cursor& at) { glfwSetCursorPos(window_, at.x, at.y); }

bool Window::right_button_down() const { return glfwGetMouseButton(window_, GLFW_MOUSE_BUTTON_RIGHT) == GLFW_PRESS; }
bool Window::left_button_down() const { return glfwGetMouseButton(window_, GLFW_MOUSE_BUTTON_LEFT) == GLFW_PRESS; }
bool Window::space_down() const { return glfwGetKey(window_, GLFW_KEY_SPACE) == GLFW_PRESS; }

std::vector<GamepadInfo> Window::gamepads() {
  std::vector<GamepadInfo> pads;
  for (int id = GLFW_JOYSTICK_1; id <= GLFW_JOYSTICK_LAST; ++id) {
    if (!glfwJoystickIsGamepad(id)) continue;
    const char* name = glfwGetGamepadName(id);
    pads.push_back({id, name ? name : "gamepad"});
  }
  return pads;
}

std::optional<GamepadReading> Window::gamepad(int id) {
  GLFWgamepadstate state;
  if (glfwGetGamepadState(id, &state) != GLFW_TRUE) return std::nullopt;
  GamepadReading reading;
  static_assert(sizeof state.axes / sizeof state.axes[0] == std::tuple_size_v<decltype(reading.axes)>);
  static_assert(sizeof state.buttons == std::tuple_size_v<decltype(reading.buttons)>);
  std::copy(std::begin(state.axes), std::end(state.axes), reading.axes.begin());
  std::copy(std::begin(state.buttons), std::end(state.buttons), reading.buttons.begin());
  return reading;
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

bool Window::take_key_press(Key key) {
  const auto end =
      std::remove_if(key_presses_.begin(), key_presses_.end(), [key](const KeyPress& p) { return p.key == key; });
  const bool taken = end != key_presses_.end();
  key_presses_.erase(end, key_presses_.end());
  return taken;
}

bool Window::take_resized() {
  bool r = resized_;
  resized_ = false;
  return r;
}

}  // namespace needle::engine
