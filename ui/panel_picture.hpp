// ImGui panels rendered offscreen through the engine's UI pass into an image, over an empty view
// or over a scene with the needle posed: the report's pictures and the panel goldens.
#pragma once

#include <functional>
#include <optional>

#include "engine/extent.hpp"
#include "engine/gpu_device.hpp"
#include "engine/rgba_image.hpp"
#include "engine/scene.hpp"
#include "engine/tissue.hpp"

namespace needle::ui {

struct PictureScene {
  engine::Scene scene;
  std::optional<engine::NeedleLoad> needle;
  float panels_fraction = 0.0f;  // the left part of the view the panels cover (frame_beside_panels)
};

// Two frames are drawn, since ImGui fits auto-sized windows on the first; the second is read back.
engine::RgbaImage panel_picture(const engine::GpuDevice& device, engine::Extent extent,
                                const std::function<void()>& draw, const PictureScene* scene = nullptr,
                                int msaa_samples = 1);

}  // namespace needle::ui
