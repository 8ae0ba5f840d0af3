#include "ui/panel_picture.hpp"

#include "engine/gpu_scene.hpp"
#include "engine/render_target.hpp"
#include "engine/ui_pass.hpp"
#include "ui/review_replay.hpp"

namespace needle::ui {

engine::RgbaImage panel_picture(const engine::GpuDevice& device, engine::Extent extent,
                                const std::function<void()>& draw, const PictureScene* picture, int msaa_samples) {
  engine::HeadlessTarget target(device, extent);
  engine::SceneRenderer renderer(device, target, {msaa_samples});
  engine::GpuScene scene = picture ? engine::GpuScene(renderer, picture->scene)
                                   : engine::GpuScene(renderer, engine::Model{}, engine::Scene{});
  engine::UiPass ui(renderer, nullptr);
  engine::RgbaImage image;
  for (int frame = 0; frame < 2; ++frame) {
    ui.begin_frame(extent, 1.0f / 60.0f);
    draw();
    const engine::NeedleLoad* needle = picture && picture->needle ? &*picture->needle : nullptr;
    engine::FrameParams params = scene.frame_params(needle);
    if (picture && picture->panels_fraction > 0.0f)
      frame_beside_panels(params.camera, float(extent.width) / float(extent.height), picture->panels_fraction);
    params.overlay = ui.end_frame();
    renderer.draw(target, params, frame == 1 ? &image : nullptr);
  }
  return image;
}

}  // namespace needle::ui
