#include "app/desk_input.hpp"

#include <cmath>
#include <stdexcept>

#include "engine/screen_projection.hpp"
#include "haptics/control/task_space_coupling.hpp"

namespace needle::app {
namespace {

std::optional<haptics::DeskKey> desk_key(engine::Key key) {
  switch (key) {
    case engine::Key::kLeft:
      return haptics::DeskKey::kLeft;
    case engine::Key::kRight:
      return haptics::DeskKey::kRight;
    case engine::Key::kDown:
      return haptics::DeskKey::kDown;
    case engine::Key::kUp:
      return haptics::DeskKey::kUp;
    case engine::Key::kS:
      return haptics::DeskKey::kOut;
    case engine::Key::kW:
      return haptics::DeskKey::kIn;
    case engine::Key::kA:
      return haptics::DeskKey::kSwingLeft;
    case engine::Key::kD:
      return haptics::DeskKey::kSwingRight;
    // Q and E tilt: R is the score panel's Retry, so no key has two meanings.
    case engine::Key::kQ:
      return haptics::DeskKey::kTiltToward;
    case engine::Key::kE:
      return haptics::DeskKey::kTiltAway;
    default:
      return std::nullopt;
  }
}

}  // namespace

int gamepad_id(const haptics::DeviceSpec& spec) {
  const std::vector<engine::GamepadInfo> pads = engine::Window::gamepads();
  if (!spec.index) {
    if (pads.empty())
      throw std::runtime_error(
          "gamepad: none connected (no gamepad with a standard mapping is present); connect one, "
          "or choose the mouse or the keyboard");
    return pads.front().id;
  }
  for (const engine::GamepadInfo& pad : pads)
    if (pad.id == *spec.index) return pad.id;
  throw std::runtime_error(spec.text() + ": no such gamepad connected (needle-sim devices lists the gamepads present)");
}

void check_present(const haptics::DeviceSpec& spec) {
  if (spec.kind == haptics::DeviceSpec::Kind::kGamepad) gamepad_id(spec);
}

DeskInput::DeskInput(haptics::DeskDevice& device, bool syringe) : device_(device), pad_({}, syringe) {
  using K = haptics::DeviceSpec::Kind;
  const haptics::DeviceSpec& spec = device.spec();
  kind_ = spec.kind == K::kMouse ? Kind::kMouse : spec.kind == K::kKeyboard ? Kind::kKeyboard : Kind::kGamepad;
  if (kind_ == Kind::kGamepad) {
    gamepad_ = true;
    gamepad_id_ = gamepad_id(spec);
  }
}

haptics::MouseView mouse_view(const engine::Camera& camera, const ToolStart& start) {
  const Eigen::Vector3d eye(camera.position.x, camera.position.y, camera.position.z);
  return {std::tan(0.5 * double(camera.fov_y_deg) * M_PI / 180.0), (start.tip - eye).dot(start.device_to_scene.col(2))};
}

haptics::NeedleDirection needle_direction(const ToolStart& start, const std::array<double, 3>& axis) {
  const Eigen::Vector3d d = start.device_to_scene.transpose() * Eigen::Vector3d(axis[0], axis[1], axis[2]).normalized();
  return {{d.x(), d.y(), d.z()}};
}

haptics::NeedleDirection needle_direction(const ToolStart& start, const haptics::DeskPose& pose) {
  const Eigen::Vector3d d =
      start.device_to_scene.transpose() *
      haptics::wrist_direction(start.device_to_scene, start.direction, pose.wrist_rad[0], pose.wrist_rad[1]);
  return {{d.x(), d.y(), d.z()}};
}

void DeskInput::frame(engine::Window& window, const std::vector<engine::Window::KeyPress>& keys,
                      bool pointer_on_panel) {
  if (start_) {
    mouse_.set_needle_direction(axis_ ? needle_direction(*start_, *axis_) : needle_direction(*start_, mouse_.pose()));
    keys_.set_needle_direction(axis_ ? needle_direction(*start_, *axis_) : needle_direction(*start_, keys_.pose()));
    pad_.set_needle_direction(axis_ ? needle_direction(*start_, *axis_) : needle_direction(*start_, pad_.pose()));
  }
  const auto now = std::chrono::steady_clock::now();
  const double dt = last_frame_ ? std::chrono::duration<double>(now - *last_frame_).count() : 0.0;
  last_frame_ = now;
  const double scroll = window.take_scroll();
  switch (kind_) {
    case Kind::kMouse: {
      if (pointer_on_panel && !turning_) return;
      const engine::Extent size = window.size();
      if (size.width == 0 || size.height == 0) return;  // minimised
      engine::Window::Cursor at = window.cursor();
      const bool turning = window.right_button_down();
      if (turning && !turning_) turn_from_ = at;
      if (!turning && turning_) {  // the turn is over: the cursor goes back to the tip
        window.set_cursor(turn_from_);
        at = turn_from_;
      }
      turning_ = turning;
      const double half = 0.5 * size.height;
      mouse_.pointer((at.x - 0.5 * size.width) / half, (half - at.y) / half, turning);
      if (scroll != 0.0 && !turning) {  // along the needle, and the cursor onto the tip's new place
        mouse_.scroll(scroll);
        double x = 0.0, y = 0.0;
        mouse_.cursor_at_handle(x, y);
        window.set_cursor({0.5 * size.width + x * half, half - y * half});
      }
      device_.set_pose(mouse_.pose());
      return;
    }
    case Kind::kKeyboard:
      for (const engine::Window::KeyPress& press : keys)
        if (const auto key = desk_key(press.key)) keys_.press(*key, press.shift);
      device_.set_pose(keys_.pose());
      return;
    case Kind::kGamepad: {
      const std::optional<engine::GamepadReading> reading = engine::Window::gamepad(gamepad_id_);
      device_.set_connected(reading.has_value());  // unplugged: the loop latches a disconnection fault
      if (!reading) return;
      haptics::GamepadState state;
      for (int i = 0; i < haptics::GamepadState::kAxes; ++i) state.axes[i] = reading->axes[size_t(i)];
      for (int i = 0; i < haptics::GamepadState::kButtons; ++i) state.buttons[i] = reading->buttons[size_t(i)];
      pad_.update(state, dt);
      device_.set_pose(pad_.pose());
      return;
    }
  }
}

void DeskInput::start_at(engine::Window& window, const engine::Camera& camera, const ToolStart& start) {
  start_ = start;
  if (kind_ != Kind::kMouse) return;
  mouse_ = haptics::MouseMapping({}, mouse_view(camera, start));
  const engine::Extent pixels = window.framebuffer_extent(), size = window.size();
  const glm::vec3 tip(float(start.tip.x()), float(start.tip.y()), float(start.tip.z()));
  const std::optional<glm::vec2> at = engine::project_to_screen(camera, pixels, tip);
  if (!at || pixels.width == 0 || pixels.height == 0) return;
  window.set_cursor({double(at->x) * size.width / pixels.width, double(at->y) * size.height / pixels.height});
}

std::string DeskInput::help(haptics::DeviceSpec::Kind kind, bool syringe) {
  using K = haptics::DeviceSpec::Kind;
  if (kind == K::kMouse)
    return std::string("cursor: move   wheel or Up/Down: in and out   right button held: turn about the tip") +
           (syringe ? "   left button or Space held: press the plunger" : "");
  if (kind == K::kKeyboard)
    return std::string("arrows: move   W/S: in and out   A/D, Q/E: turn about the tip   Shift: fine") +
           (syringe ? "   Space held: press the plunger" : "");
  if (syringe)
    return "left stick: move   right trigger: in (out with LB)   right stick: turn about the tip   left trigger: press "
           "the "
           "plunger   Start: reset a fault";
  return "left stick: move   triggers: in and out   right stick: turn about the tip   Start: reset a fault";
}

}  // namespace needle::app
