// ImGui panels rendered offscreen through the engine's UI pass into an image, over an empty view
// or over a scene with the needle posed: the report's pictures and the panel goldens.
#pragma once

#include <functional>
#include <optional>

#include "engine/deformation_field.hpp"
#include "engine/rgba_image.hpp"
#include "engine/scene.hpp"
#include "engine/scene_renderer.hpp"

namespace needle::engine {
class VulkanContext;
}

namespace needle::ui {

struct PictureScene {
  engine::Scene scene;
  std::optional<engine::NeedleLoad> needle;
  float panels_fraction = 0.0f;  // the left part of the view the panels cover (frame_beside_panels)
};

// Two frames are drawn, since ImGui fits auto-sized windows on the first; the second is read back.
engine::RgbaImage panel_picture(const engine::VulkanContext& context, VkExtent2D extent, const std::function<void()>& draw,
                                const PictureScene* scene = nullptr,
                                VkSampleCountFlagBits msaa = VK_SAMPLE_COUNT_1_BIT);

}  // namespace needle::ui
