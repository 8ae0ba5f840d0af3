// The review's replay view: the 3D view framed beside the review's panels (the recorded needle
// itself comes from app/replay_cursor.hpp).
#pragma once

#include "engine/scene.hpp"

namespace needle::ui {

// Moves the camera so that what it looked at lands in the middle of the part of the view right
// of panels covering `left_fraction` of its width, and backs it off so the scene fits there.
void frame_beside_panels(engine::Camera& camera, float aspect, float left_fraction);

}  // namespace needle::ui
