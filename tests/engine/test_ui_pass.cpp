// The UI pass draws ImGui inside the scene's render pass on a headless target, frame after
// frame, validation-clean; the panel covers its corner and leaves the rest of the view alone.
#include <gtest/gtest.h>
#include <imgui.h>

#include "engine/gpu_scene.hpp"
#include "engine/render_target.hpp"
#include "engine/ui_pass.hpp"
#include "vulkan_fixture.hpp"

namespace needle::test {
namespace {

class UiPassTest : public VulkanTest {};

TEST_F(UiPassTest, PanelIsDrawnOverTheSceneHeadless) {
  const engine::Extent extent{200, 120};
  engine::HeadlessTarget target(device(), extent);
  engine::SceneRenderer renderer(device(), target);
  engine::Scene view;
  view.background = {0.0f, 0.0f, 0.0f};
  engine::GpuScene scene(renderer, engine::Model{}, view);
  engine::UiPass ui(renderer, nullptr);

  engine::RgbaImage image;
  for (int frame = 0; frame < 4; ++frame) {  // more frames than the backend's buffer sets cycle through
    ui.begin_frame(extent, 1.0f / 60.0f);
    ImGui::SetNextWindowPos(ImVec2(10, 10));
    ImGui::SetNextWindowSize(ImVec2(100, 50));
    ImGui::Begin("test panel", nullptr, ImGuiWindowFlags_NoDecoration);
    ImGui::TextUnformatted("NEEDLE");
    ImGui::End();
    engine::FrameParams params = scene.frame_params();
    params.overlay = ui.end_frame();
    ASSERT_TRUE(renderer.draw(target, params, frame == 3 ? &image : nullptr));
  }
  auto brightness = [&](uint32_t x, uint32_t y) {
    return int(image.at(x, y)[0]) + image.at(x, y)[1] + image.at(x, y)[2];
  };
  // Outside the panel: the black background, untouched.
  EXPECT_EQ(brightness(5, 5), 0);
  EXPECT_EQ(brightness(150, 100), 0);
  // Inside: ImGui's window background (not black) and the text (bright glyph pixels).
  EXPECT_GT(brightness(100, 50), 0);
  int brightest = 0;
  for (uint32_t y = 12; y < 40; ++y)
    for (uint32_t x = 12; x < 80; ++x) brightest = std::max(brightest, brightness(x, y));
  EXPECT_GT(brightest, 500) << "no text drawn in the panel";
}

}  // namespace
}  // namespace needle::test
