#include "engine/ultrasound/ultrasound_display.hpp"

#include <algorithm>
#include <cmath>

#include "engine/passes/scene_pass.hpp"
#include "engine/ultrasound/ultrasound_pass.hpp"
#include "engine/vulkan/vulkan_context.hpp"
#include "spirv/ultrasound_show_frag.h"

namespace needle::engine {

UltrasoundDisplay::UltrasoundDisplay(const ScenePass& scene_pass, const UltrasoundPass& ultrasound)
    : scene_pass_(scene_pass),
      quad_(scene_pass.context().device(), ultrasound_show_frag_spv, sizeof(ultrasound_show_frag_spv),
            scene_pass.render_pass(), scene_pass.samples()) {
  quad_.set_image(ultrasound.image_view());
}

void UltrasoundDisplay::record(VkCommandBuffer cmd, ScreenRect rect, VkExtent2D target) const {
  const float x0 = std::max(0.0f, rect.x), y0 = std::max(0.0f, rect.y);
  const float x1 = std::min(float(target.width), rect.x + rect.width),
              y1 = std::min(float(target.height), rect.y + rect.height);
  if (x1 <= x0 || y1 <= y0) return;
  const VkViewport viewport{rect.x, rect.y, rect.width, rect.height, 0.0f, 1.0f};
  const VkRect2D scissor{{int32_t(std::floor(x0)), int32_t(std::floor(y0))},
                         {uint32_t(std::ceil(x1) - std::floor(x0)), uint32_t(std::ceil(y1) - std::floor(y0))}};
  quad_.record(cmd, viewport, scissor);
}

}  // namespace needle::engine
