// Turns the haptic loop's newest ToolSnapshot into the needle load the deformation pass needs.
// It lives in the application layer because it joins the haptics' state to the engine's input:
// neither includes the other.
//
// The thesis's single-surface tissue: the contact state says Free, Touching (rigid surface) or
// Inserted, and the snapshot does not say where the needle entered, so the tracker remembers
// the tip where the first snapshot in tissue found it (at 60 frames a second against a 1 kHz
// loop, within a few hundred micrometres of the true entry at insertion speeds).
//
// A layered tissue ("visual agreement" with the touch): the dimple comes from the tissue model's own
// surface deflection (ToolSnapshot::tissue). Before the track has passed into any layer, the tip
// pressing a surface is Touching at the physics' rest point where it met it; once a layer is
// passed it is Inserted with the entry where the first surface gave way (the physics' surface
// point at the puncture). The tracker must see every snapshot in tick order to catch that
// point (the feed and the replay do): a layer with no surface is entered in the tick it is met,
// and then the entry is the tip of that tick.
//
// The lateral multipliers are read along the y and z axes of the snapshot's orientation, taken
// to be the needle frame's y5 and z5.
#pragma once

#include <optional>

#include "engine/tissue.hpp"
#include "haptics/realtime/tool_snapshot.hpp"
#include "training/tasks/task.hpp"

namespace needle::app {

enum class TissueKind {
  SingleSurface,  // the thesis's penetrable tissue: the contact state alone
  Layered,        // a scenario with tissue layers: the snapshot's tissue state
};

// A task's tissue, as the review's and the panel's "layered" read it: more than one layer.
inline TissueKind tissue_kind(const training::Task& task) {
  return task.layers.size() > 1 ? TissueKind::Layered : TissueKind::SingleSurface;
}

class NeedleTracker {
 public:
  explicit NeedleTracker(TissueKind kind = TissueKind::SingleSurface) : kind_(kind) {}
  engine::NeedleLoad update(const haptics::ToolSnapshot& snapshot);

 private:
  TissueKind kind_;
  std::optional<glm::dvec3> entry_;    // set while the needle is in tissue
  std::optional<glm::dvec3> pressed_;  // layered: the rest point of the surface the tip presses
};

}  // namespace needle::app
