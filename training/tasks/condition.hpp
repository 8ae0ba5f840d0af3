// A step's success condition evaluated on one haptic state (docs/TASKS.md), without its hold time.
#pragma once

#include "haptics/realtime/tool_snapshot.hpp"
#include "training/tasks/task.hpp"

namespace needle::training {

bool contact_matches(ContactRequirement required, haptics::ContactState contact);

// Depth of the tip along an axis marker, measured from its origin along its direction (m).
double depth_along(const Marker& axis, const Vec3& tip);

// True when `state` satisfies `c` at this instant (the hold time is the caller's business).
bool condition_holds(const Task& task, const Condition& c, const haptics::ToolSnapshot& state);

}  // namespace needle::training
