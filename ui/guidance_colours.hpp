// The guidance's colours, one per kind of cue, shared by the marks over the 3D view
// (ui/guidance_overlay.cpp) and the trainee panel's gauges (ui/trainee_gauges.cpp), so a gauge reads
// as the mark it measures.
#pragma once

#include <imgui.h>

namespace needle::ui {

inline const ImU32 kEntryColour = IM_COL32(80, 200, 255, 255);        // the entry ring, the distance to it
inline const ImU32 kAxisColour = IM_COL32(255, 210, 40, 255);         // the planned axis, the angle off it
inline const ImU32 kTargetColour = IM_COL32(255, 90, 70, 255);        // the target ring
inline const ImU32 kBandColour = IM_COL32(30, 190, 70, 255);          // the depth band
inline const ImU32 kLayerStartColour = IM_COL32(215, 235, 255, 255);  // where a layer begins along the axis

}  // namespace needle::ui
