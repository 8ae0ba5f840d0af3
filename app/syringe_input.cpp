#include "app/syringe_input.hpp"

namespace needle::app {

SyringeInput::SyringeInput(haptics::SyringeHandDevice& hand, haptics::DeviceSpec::Kind device,
                           std::optional<int> gamepad)
    : hand_(hand), mouse_(device == haptics::DeviceSpec::Kind::kMouse), gamepad_(gamepad) {}

void SyringeInput::frame(engine::Window& window, bool pointer_on_panel) {
  const auto now = std::chrono::steady_clock::now();
  const double dt = last_frame_ ? std::chrono::duration<double>(now - *last_frame_).count() : 0.0;
  last_frame_ = now;
  keys_.held(window.space_down() || (mouse_ && !pointer_on_panel && window.left_button_down()), dt);
  if (gamepad_) {
    const std::optional<engine::GamepadReading> pad = engine::Window::gamepad(*gamepad_);
    trigger_.trigger(pad ? pad->axes[size_t(haptics::GamepadState::kLeftTrigger)] : -1.0);
  }
  hand_.set_thumb_force(force_N());
}

}  // namespace needle::app
