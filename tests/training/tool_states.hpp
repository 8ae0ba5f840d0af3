// Haptic states built by hand for the task and scoring tests.
#pragma once

#include <cmath>

#include "haptics/realtime/tick_sample.hpp"
#include "training/tasks/vec3.hpp"

namespace needle::training::test {

// A state at time t with the tip at p, the needle axis turned from +x about +y by `pitch`
// (so it points along (cos pitch, 0, -sin pitch)), and the given contact.
inline haptics::ToolSnapshot state(double t, const Vec3& p, double pitch = 0.0,
                                   haptics::ContactState contact = haptics::ContactState::kFree) {
  haptics::ToolSnapshot s;
  s.time_s = t;
  for (int i = 0; i < 3; ++i) s.needle_tip_m[i] = p[i];
  s.needle_orientation[0] = std::cos(pitch / 2);
  s.needle_orientation[2] = std::sin(pitch / 2);
  s.contact = contact;
  return s;
}

inline haptics::TickSample sample(const haptics::ToolSnapshot& s) {
  haptics::TickSample out;
  out.state = s;
  return out;
}

}  // namespace needle::training::test
