#include "app/desk_input.hpp"

#include <GLFW/glfw3.h>

#include <stdexcept>

#include "engine/screen_projection.hpp"

namespace needle::app {
namespace {

std::optional<haptics::DeskKey> desk_key(int key) {
  switch (key) {
    case GLFW_KEY_LEFT: return haptics::DeskKey::kLeft;
    case GLFW_KEY_RIGHT: return haptics::DeskKey::kRight;
    case GLFW_KEY_DOWN: return haptics::DeskKey::kDown;
    case GLFW_KEY_UP: return haptics::DeskKey::kUp;
    case GLFW_KEY_S: return haptics::DeskKey::kOut;
    case GLFW_KEY_W: return haptics::DeskKey::kIn;
    case GLFW_KEY_A: return haptics::DeskKey::kSwingLeft;
    case GLFW_KEY_D: return haptics::DeskKey::kSwingRight;
    case GLFW_KEY_F: return haptics::DeskKey::kTiltToward;
    case GLFW_KEY_R: return haptics::DeskKey::kTiltAway;
    default: return std::nullopt;
  }
}

}  // namespace

std::vector<GamepadInfo> present_gamepads() {
  std::vector<GamepadInfo> pads;
  for (int id = GLFW_JOYSTICK_1; id <= GLFW_JOYSTICK_LAST; ++id) {
    if (!glfwJoystickIsGamepad(id)) continue;
    const char* name = glfwGetGamepadName(id);
    pads.push_back({id, name ? name : "gamepad"});
  }
  return pads;
}

int gamepad_id(const haptics::DeviceSpec& spec) {
  const std::vector<GamepadInfo> pads = present_gamepads();
  if (!spec.index) {
    if (pads.empty())
      throw std::runtime_error("gamepad: none connected (GLFW reports no gamepad with a standard mapping); connect one, "
                               "or choose the mouse or the keyboard");
    return pads.front().id;
  }
  for (const GamepadInfo& pad : pads)
    if (pad.id == *spec.index) return pad.id;
  throw std::runtime_error(spec.text() + ": no such gamepad connected (needle-sim lists the gamepads GLFW reports on its start screen)");
}

void check_present(const haptics::DeviceSpec& spec) {
  if (spec.kind == haptics::DeviceSpec::Kind::kGamepad) gamepad_id(spec);
}

DeskInput::DeskInput(haptics::DeskDevice& device) : device_(device) {
  using K = haptics::DeviceSpec::Kind;
  const haptics::DeviceSpec& spec = device.spec();
  kind_ = spec.kind == K::kMouse ? Kind::kMouse : spec.kind == K::kKeyboard ? Kind::kKeyboard : Kind::kGamepad;
  if (kind_ == Kind::kGamepad) {
    gamepad_ = true;
    gamepad_id_ = gamepad_id(spec);
  }
}

void DeskInput::frame(engine::Window& window, const std::vector<engine::Window::KeyPress>& keys, bool pointer_on_panel) {
  const auto now = std::chrono::steady_clock::now();
  const double dt = last_frame_ ? std::chrono::duration<double>(now - *last_frame_).count() : 0.0;
  last_frame_ = now;
  const double scroll = window.take_scroll();
  switch (kind_) {
    case Kind::kMouse: {
      if (pointer_on_panel && !turning_) return;
      GLFWwindow* handle = window.handle();
      int width = 0, height = 0;
      glfwGetWindowSize(handle, &width, &height);
      if (width <= 0 || height <= 0) return;  // minimised
      double px = 0.0, py = 0.0;
      glfwGetCursorPos(handle, &px, &py);
      const bool turning = glfwGetMouseButton(handle, GLFW_MOUSE_BUTTON_RIGHT) == GLFW_PRESS;
      if (turning && !turning_) turn_from_[0] = px, turn_from_[1] = py;
      if (!turning && turning_) {  // the turn is over: the cursor goes back to the tip
        glfwSetCursorPos(handle, turn_from_[0], turn_from_[1]);
        px = turn_from_[0], py = turn_from_[1];
      }
      turning_ = turning;
      const double half = 0.5 * height;
      mouse_.pointer((px - 0.5 * width) / half, (half - py) / half, turning);
      mouse_.scroll(scroll);
      device_.set_pose(mouse_.pose());
      return;
    }
    case Kind::kKeyboard:
      for (const engine::Window::KeyPress& press : keys)
        if (const auto key = desk_key(press.key)) keys_.press(*key, press.shift);
      device_.set_pose(keys_.pose());
      return;
    case Kind::kGamepad: {
      GLFWgamepadstate glfw_state;
      const bool present = glfwGetGamepadState(gamepad_id_, &glfw_state) == GLFW_TRUE;
      device_.set_connected(present);  // unplugged: the loop latches a disconnection fault
      if (!present) return;
      haptics::GamepadState state;
      for (int i = 0; i < haptics::GamepadState::kAxes; ++i) state.axes[i] = glfw_state.axes[i];
      for (int i = 0; i < haptics::GamepadState::kButtons; ++i) state.buttons[i] = glfw_state.buttons[i];
      pad_.update(state, dt);
      device_.set_pose(pad_.pose());
      return;
    }
  }
}

void DeskInput::place_cursor(engine::Window& window, const engine::Camera& camera, const glm::vec3& world) {
  if (kind_ != Kind::kMouse) return;
  const engine::Extent pixels = window.framebuffer_extent();
  int width = 0, height = 0;
  glfwGetWindowSize(window.handle(), &width, &height);
  const std::optional<glm::vec2> at = engine::project_to_screen(camera, pixels, world);
  if (!at || pixels.width == 0 || pixels.height == 0) return;
  glfwSetCursorPos(window.handle(), at->x * width / pixels.width, at->y * height / pixels.height);
}

const char* DeskInput::help(haptics::DeviceSpec::Kind kind) {
  if (kind == haptics::DeviceSpec::Kind::kMouse) return "cursor: move   wheel or Up/Down: in and out   right button held: turn about the tip";
  if (kind == haptics::DeviceSpec::Kind::kKeyboard) return "arrows: move   W/S: in and out   A/D, R/F: turn about the tip   Shift: fine";
  return "left stick: move   triggers: in and out   right stick: turn about the tip   Start: reset a fault";
}

}  // namespace needle::app
