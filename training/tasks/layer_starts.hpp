// Where along a planned axis each tissue layer begins (the depth gauge marks the layer
// boundaries): computed once when the task is read, from the scenario's layer geometry at rest.
#pragma once

#include <vector>

#include "haptics/tissue/tissue_model.hpp"
#include "training/tasks/task.hpp"

namespace needle::training {

// The span along the axis that is searched: from this far behind the origin (an entry marked a
// little above the skin still finds the skin) to this far ahead. Design values: the shipped axes
// start on the skin and their targets lie under 60 mm deep.
inline constexpr double kLayerSearchBehind_m = 0.03;
inline constexpr double kLayerSearchAhead_m = 0.12;
// The march's step: a layer thinner than this along the axis can be missed (the thinnest shipped
// layer, the dura, is 0.5 mm). Each change is then bisected to kLayerStartTolerance_m.
inline constexpr double kLayerSearchStep_m = 5e-5;
inline constexpr double kLayerStartTolerance_m = 1e-7;

// (tissue at rest, the origin of its frame in the world (a scenario's base_in_world), axis origin
// in the world, unit direction) => every change of the layer holding the point along the axis
// (haptics::TissueModel::layer_at), in order of depth, between kLayerSearchBehind_m behind the
// origin and kLayerSearchAhead_m ahead. Empty for an empty tissue.
std::vector<LayerStart> layer_starts_along(const haptics::TissueModel& tissue, const Vec3& tissue_frame_in_world,
                                           const Vec3& origin, const Vec3& direction);

}  // namespace needle::training
