// The window's side of the syringe hand (docs/DEVICES.md, "The syringe hand"): each frame the app
// reads the space bar, the mouse's left button (the mouse device, over the view) or a gamepad's left
// trigger through engine::Window, turns it into the thumb's force on the plunger
// (haptics::PlungerMapping) and sets it on the session's syringe hand, lock-free.
#pragma once

#include <algorithm>
#include <chrono>
#include <optional>

#include "engine/window.hpp"
#include "haptics/devices/desk_mapping.hpp"
#include "haptics/devices/device_spec.hpp"
#include "haptics/devices/syringe_hand.hpp"

namespace needle::app {

class SyringeInput {
 public:
  // `gamepad`: the slot of the gamepad whose left trigger presses (the gamepad device's), if any.
  SyringeInput(haptics::SyringeHandDevice& hand, haptics::DeviceSpec::Kind device, std::optional<int> gamepad);

  // One frame: `pointer_on_panel`, the cursor is over a panel (its clicks are the panel's).
  void frame(engine::Window& window, bool pointer_on_panel);
  double force_N() const { return std::max(keys_.force_N(), trigger_.force_N()); }

 private:
  haptics::SyringeHandDevice& hand_;
  bool mouse_ = false;
  std::optional<int> gamepad_;
  haptics::PlungerMapping keys_, trigger_;
  std::optional<std::chrono::steady_clock::time_point> last_frame_;
};

}  // namespace needle::app
