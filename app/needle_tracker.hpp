// Turns the haptic loop's newest ToolSnapshot into the needle load the deformation pass needs.
// The snapshot says where the needle is and which constraint holds it, not where it entered the
// tissue, so the tracker remembers that: the tip where the first snapshot in tissue found it (at
// 60 frames a second against a 1 kHz loop, within a few hundred micrometres of the true entry
// at insertion speeds). The lateral multipliers are read along the y and z axes of the
// snapshot's orientation, taken to be the needle frame's y5 and z5. It lives in the application
// layer because it joins the haptics' state to the engine's input: neither includes the other.
#pragma once

#include <optional>

#include "engine/tissue.hpp"
#include "haptics/realtime/tool_snapshot.hpp"

namespace needle::app {

class NeedleTracker {
 public:
  engine::NeedleLoad update(const haptics::ToolSnapshot& snapshot);

 private:
  std::optional<glm::dvec3> entry_;  // set while the needle is in tissue
};

}  // namespace needle::app
